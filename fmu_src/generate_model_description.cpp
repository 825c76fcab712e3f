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
        case Causality::parameter: return "parameter";
        case Causality::input: return "input";
        case Causality::output: return "output";
    }
    return "";
}

const char* name(Variability v) {
    switch (v) {
        case Variability::fixed: return "fixed";
        case Variability::tunable: return "tunable";
        case Variability::continuous: return "continuous";
        case Variability::discrete: return "discrete";
    }
    return "";
}

// Text for an XML attribute value.
std::string escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
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
    {"m/s", R"(m="1" s="-1")"},
    {"kg/m3", R"(kg="1" m="-3")"},
    {"kg/m", R"(kg="1" m="-1")"},
    {"Pa", R"(kg="1" m="-1" s="-2")"},
    {"N/m", R"(kg="1" s="-2")"},
    {"J/m", R"(kg="1" m="1" s="-2")"},
};

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: generate_model_description OUTPUT.xml\n";
        return 2;
    }
    std::ostringstream x;
    x << R"(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription
  fmiVersion="2.0"
  modelName=")" << model_identifier << R"("
  guid=")" << guid << R"("
  description="Plane-strain elastic body in frictional contact with a moving rigid foundation: Ligursky and Renard mass redistribution on the normal component, midpoint time stepping"
  generationTool="ContactBody generate_model_description"
  variableNamingConvention="structured"
  numberOfEventIndicators="0">
  <CoSimulation
    modelIdentifier=")" << model_identifier << R"("
    canHandleVariableCommunicationStepSize="true"
    canInterpolateInputs="true"
    maxOutputDerivativeOrder="0"
    canRunAsynchronuously="false"
    canBeInstantiatedOnlyOncePerProcess="false"
    canNotUseMemoryManagementFunctions="true"
    canGetAndSetFMUstate="true"
    canSerializeFMUstate="true"
    providesDirectionalDerivative="false"/>
  <UnitDefinitions>
)";
    for (const auto& [unit, exponents] : units)
        x << "    <Unit name=\"" << unit << "\"><BaseUnit " << exponents << "/></Unit>\n";
    x << R"(  </UnitDefinitions>
  <TypeDefinitions>
)";
    for (const EnumerationType& t : enumeration_types()) {
        x << "    <SimpleType name=\"" << t.name << "\">\n      <Enumeration>\n";
        for (size_t k = 0; k < t.items.size(); ++k)
            x << "        <Item name=\"" << t.items[k] << "\" value=\"" << k << "\"/>\n";
        x << "      </Enumeration>\n    </SimpleType>\n";
    }
    x << R"(  </TypeDefinitions>
  <LogCategories>
)";
    for (const std::string& c : log_categories()) x << "    <Category name=\"" << c << "\"/>\n";
    x << R"(  </LogCategories>
  <DefaultExperiment startTime="0" stopTime="0.02" stepSize="0.0001"/>
  <ModelVariables>
)";
    std::vector<size_t> outputs;
    size_t index = 0;
    for (const Variable& v : variables()) {
        ++index;
        if (v.causality == Causality::output) outputs.push_back(index);
        x << "    <!-- " << index << " --><ScalarVariable name=\"" << v.name
          << "\" valueReference=\"" << v.value_reference << "\" description=\"" << escaped(v.description)
          << "\" causality=\"" << name(v.causality) << "\" variability=\"" << name(v.variability)
          << "\"";
        if (v.causality == Causality::output) x << " initial=\"calculated\"";
        x << ">\n      <";
        switch (v.type) {
            case Type::Real: x << "Real"; break;
            case Type::Integer: x << "Integer"; break;
            case Type::Enumeration:
                x << "Enumeration declaredType=\"" << enumeration_type(v).name << "\"";
                break;
            case Type::String: x << "String"; break;
        }
        if (*v.unit) x << " unit=\"" << v.unit << "\"";
        if (v.type == Type::Real || v.type == Type::Integer) {
            if (!std::isnan(v.min)) x << " min=\"" << number(v.min) << "\"";
            if (!std::isnan(v.max) && std::isfinite(v.max)) x << " max=\"" << number(v.max) << "\"";
        }
        if (v.type == Type::String) x << " start=\"\"";
        else if (v.causality != Causality::output) x << " start=\"" << number(v.start) << "\"";
        x << "/>\n    </ScalarVariable>\n";
    }
    x << "  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n";
    for (size_t i : outputs) x << "      <Unknown index=\"" << i << "\"/>\n";
    x << "    </Outputs>\n    <InitialUnknowns>\n";
    for (size_t i : outputs) x << "      <Unknown index=\"" << i << "\"/>\n";
    x << "    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n";

    std::ofstream out(argv[1]);
    out << x.str();
    if (!out) {
        std::cerr << "cannot write " << argv[1] << "\n";
        return 1;
    }
    return 0;
}
