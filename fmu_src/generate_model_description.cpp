// Writes modelDescription.xml from the variable table (the single source of the variables).
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "variables.hpp"

using namespace contactbody::fmu;

namespace {

const char* name(Causality c) {
    switch (c) {
        case Causality::parameter:
            return "parameter";
        case Causality::input:
            return "input";
        case Causality::output:
            return "output";
    }
    return "";
}

const char* name(Variability v) {
    switch (v) {
        case Variability::fixed:
            return "fixed";
        case Variability::tunable:
            return "tunable";
        case Variability::continuous:
            return "continuous";
        case Variability::discrete:
            return "discrete";
    }
    return "";
}

// Text for an XML attribute value.
std::string escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

// The shortest decimal that reads back as x (0.1, not 0.10000000000000001).
std::string number(double x) {
    if (x == std::floor(x) && std::abs(x) < 1e15) return std::to_string(static_cast<long long>(x));
    for (int digits = 1;; ++digits) {
        std::ostringstream s;
        s.precision(digits);
        s << x;
        if (std::stod(s.str()) == x || digits >= 17) return s.str();
    }
}

// SI base-unit exponents of the units the variables use.
const std::map<std::string, std::string> units = {
    {"m", R"(m="1")"},
    {"s", R"(s="1")"},
    {"1/s", R"(s="-1")"},
    {"s/m", R"(m="-1" s="1")"},
    {"m/s", R"(m="1" s="-1")"},
    {"kg/m3", R"(kg="1" m="-3")"},
    {"kg/m", R"(kg="1" m="-1")"},
    {"Pa", R"(kg="1" m="-1" s="-2")"},
    {"N/m", R"(kg="1" s="-2")"},
    {"J/m", R"(kg="1" m="1" s="-2")"},
    {"kg", R"(kg="1")"},
    {"N", R"(kg="1" m="1" s="-2")"},
    {"J", R"(kg="1" m="2" s="-2")"},
};

constexpr const char* description = per_body(
    "Plane-strain elastic body in frictional contact with a moving rigid foundation: Ligursky "
    "and Renard mass redistribution on the normal component, midpoint time stepping",
    "3D elastic body (a tetrahedral mesh) in isotropic frictional contact with a rigid plane "
    "sliding in x and z: Ligursky and Renard mass redistribution on the normal component, "
    "midpoint time stepping");

// The units this model's variables use (each declared once: an importer checks them).
void write_units(std::ostream& x) {
    x << "  <UnitDefinitions>\n";
    for (const auto& [unit, exponents] : units) {
        bool used = false;
        for (const Variable& v : variables()) used = used || unit == v.unit;
        if (used) x << "    <Unit name=\"" << unit << "\"><BaseUnit " << exponents << "/></Unit>\n";
    }
    x << "  </UnitDefinitions>\n";
}

// The enumeration types the standard's variables use.
std::vector<const EnumerationType*> used_enumerations(Standard standard) {
    std::vector<const EnumerationType*> used;
    for (const EnumerationType& t : enumeration_types())
        for (const Variable& v : variables())
            if (v.in(standard) && v.enumeration && t.name == std::string(v.enumeration)) {
                used.push_back(&t);
                break;
            }
    return used;
}

void write_log_categories_and_experiment(std::ostream& x) {
    x << "  <LogCategories>\n";
    for (const std::string& c : log_categories()) x << "    <Category name=\"" << c << "\"/>\n";
    x << "  </LogCategories>\n"
      << "  <DefaultExperiment startTime=\"0\" stopTime=\"0.02\" stepSize=\"0.0001\"/>\n";
}

void write_limits(std::ostream& x, const Variable& v) {
    if (v.type == Type::String || v.type == Type::Enumeration) return;
    if (!std::isnan(v.min)) x << " min=\"" << number(v.min) << "\"";
    if (!std::isnan(v.max) && std::isfinite(v.max)) x << " max=\"" << number(v.max) << "\"";
}

std::string fmi2(void) {
    std::ostringstream x;
    x << R"(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription
  fmiVersion="2.0"
  modelName=")"
      << model_identifier << R"("
  guid=")"
      << guid << R"("
  description=")"
      << description << R"("
  generationTool="ContactBody generate_model_description"
  variableNamingConvention="structured"
  numberOfEventIndicators="0">
  <CoSimulation
    modelIdentifier=")"
      << model_identifier << R"("
    canHandleVariableCommunicationStepSize="true"
    canInterpolateInputs="true"
    maxOutputDerivativeOrder="0"
    canRunAsynchronuously="false"
    canBeInstantiatedOnlyOncePerProcess="false"
    canNotUseMemoryManagementFunctions="true"
    canGetAndSetFMUstate="true"
    canSerializeFMUstate="true"
    providesDirectionalDerivative="false"/>
)";
    write_units(x);
    x << "  <TypeDefinitions>\n";
    for (const EnumerationType* t : used_enumerations(Standard::fmi2)) {
        x << "    <SimpleType name=\"" << t->name << "\">\n      <Enumeration>\n";
        for (size_t k = 0; k < t->items.size(); ++k)
            x << "        <Item name=\"" << t->items[k] << "\" value=\"" << k << "\"/>\n";
        x << "      </Enumeration>\n    </SimpleType>\n";
    }
    x << "  </TypeDefinitions>\n";
    write_log_categories_and_experiment(x);
    x << "  <ModelVariables>\n";
    std::vector<size_t> outputs;
    size_t index = 0;
    for (const Variable& v : variables()) {
        if (!v.in(Standard::fmi2)) continue;
        ++index;
        if (v.causality == Causality::output) outputs.push_back(index);
        x << "    <!-- " << index << " --><ScalarVariable name=\"" << v.name << "\" valueReference=\""
          << v.value_reference << "\" description=\"" << escaped(v.description) << "\" causality=\""
          << name(v.causality) << "\" variability=\"" << name(v.variability) << "\"";
        if (v.causality == Causality::output) x << " initial=\"calculated\"";
        x << ">\n      <";
        switch (v.type) {
            case Type::Real:
                x << "Real";
                break;
            case Type::Integer:
                x << "Integer";
                break;
            case Type::Enumeration:
                x << "Enumeration declaredType=\"" << enumeration_type(v).name << "\"";
                break;
            case Type::String:
                x << "String";
                break;
        }
        if (*v.unit) x << " unit=\"" << v.unit << "\"";
        write_limits(x, v);
        if (v.type == Type::String)
            x << " start=\"" << escaped(v.string_start) << "\"";
        else if (v.causality != Causality::output)
            x << " start=\"" << number(v.start) << "\"";
        x << "/>\n    </ScalarVariable>\n";
    }
    x << "  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n";
    for (size_t i : outputs) x << "      <Unknown index=\"" << i << "\"/>\n";
    x << "    </Outputs>\n    <InitialUnknowns>\n";
    for (size_t i : outputs) x << "      <Unknown index=\"" << i << "\"/>\n";
    x << "    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n";
    return x.str();
}

// FMI 3.0: the same table, with FMI 3.0's types, the structural parameters, the independent
// variable time, and the contact-edge arrays sized by edge_nodes.
std::string fmi3(void) {
    std::ostringstream x;
    x << R"(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription
  fmiVersion="3.0"
  modelName=")"
      << model_identifier << R"("
  instantiationToken=")"
      << guid << R"("
  description=")"
      << description << R"("
  generationTool="ContactBody generate_model_description"
  variableNamingConvention="structured">
  <CoSimulation
    modelIdentifier=")"
      << model_identifier << R"("
    canHandleVariableCommunicationStepSize="true"
    canGetAndSetFMUState="true"
    canSerializeFMUState="true"
    providesDirectionalDerivatives="false"
    providesAdjointDerivatives="false"
    providesPerElementDependencies="false"
    maxOutputDerivativeOrder="0"
    providesIntermediateUpdate="false"
    mightReturnEarlyFromDoStep="false"
    canReturnEarlyAfterIntermediateUpdate="false"
    hasEventMode="false"
    providesEvaluateDiscreteStates="false"/>
)";
    write_units(x);
    x << "  <TypeDefinitions>\n";
    for (const EnumerationType* t : used_enumerations(Standard::fmi3)) {
        x << "    <EnumerationType name=\"" << t->name << "\">\n";
        for (size_t k = 0; k < t->items.size(); ++k)
            x << "      <Item name=\"" << t->items[k] << "\" value=\"" << k << "\"/>\n";
        x << "    </EnumerationType>\n";
    }
    x << "  </TypeDefinitions>\n";
    write_log_categories_and_experiment(x);
    x << "  <ModelVariables>\n"
      << "    <Float64 name=\"time\" valueReference=\"" << time_value_reference
      << "\" causality=\"independent\" variability=\"continuous\" unit=\"s\" description=\"Simulation "
         "time\"/>\n";
    unsigned edge_nodes_reference = 0;
    for (const Variable& v : variables())
        if (v.name == std::string("edge_nodes")) edge_nodes_reference = v.value_reference;
    std::vector<unsigned> outputs;
    for (const Variable& v : variables()) {
        if (!v.in(Standard::fmi3)) continue;
        const char* element = v.type == Type::Enumeration ? "Enumeration" : fmi3_type(v);
        const char* causality = v.structural ? "structuralParameter" : name(v.causality);
        if (v.causality == Causality::output) outputs.push_back(v.value_reference);
        x << "    <" << element << " name=\"" << v.name << "\" valueReference=\"" << v.value_reference
          << "\" description=\"" << escaped(v.description) << "\" causality=\"" << causality
          << "\" variability=\"" << name(v.variability) << "\"";
        if (v.type == Type::Enumeration) x << " declaredType=\"" << enumeration_type(v).name << "\"";
        if (*v.unit) x << " unit=\"" << v.unit << "\"";
        write_limits(x, v);
        if (v.causality != Causality::output && v.type != Type::String)
            x << " start=\"" << number(v.start) << "\"";
        if (v.type == Type::String)
            x << ">\n      <Start value=\"" << escaped(v.string_start) << "\"/>\n    </String>\n";
        else if (v.is_array())
            x << ">\n      <Dimension valueReference=\"" << edge_nodes_reference << "\"/>\n    </" << element
              << ">\n";
        else
            x << "/>\n";
    }
    x << "  </ModelVariables>\n  <ModelStructure>\n";
    for (unsigned vr : outputs) x << "    <Output valueReference=\"" << vr << "\"/>\n";
    for (unsigned vr : outputs) x << "    <InitialUnknown valueReference=\"" << vr << "\"/>\n";
    x << "  </ModelStructure>\n</fmiModelDescription>\n";
    return x.str();
}

}  // namespace

int main(int argc, char** argv) {
    const bool v3 = argc == 3 && std::string(argv[1]) == "--fmi3";
    if (argc != 2 && !v3) {
        std::cerr << "usage: generate_model_description [--fmi3] OUTPUT.xml\n";
        return 2;
    }
    const char* path = argv[argc - 1];
    std::ofstream out(path);
    out << (v3 ? fmi3() : fmi2());
    if (!out) {
        std::cerr << "cannot write " << path << "\n";
        return 1;
    }
    return 0;
}
