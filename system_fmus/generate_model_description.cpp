// Writes a companion model's modelDescription.xml from its variable table (at build time).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "companion.hpp"

namespace {

// SI base-unit exponents of the units the companions use.
const std::map<std::string, std::string> units = {
    {"kg", R"(kg="1")"},
    {"kg.m2", R"(kg="1" m="2")"},
    {"m", R"(m="1")"},
    {"s", R"(s="1")"},
    {"N", R"(kg="1" m="1" s="-2")"},
    {"N/m", R"(kg="1" s="-2")"},
    {"N.m", R"(kg="1" m="2" s="-2")"},
    {"J", R"(kg="1" m="2" s="-2")"},
    {"m/s", R"(m="1" s="-1")"},
    {"rad/s", R"(s="-1" rad="1")"},
    {"N.m/rad", R"(kg="1" m="2" s="-2" rad="-1")"},
    {"N.m.s/rad", R"(kg="1" m="2" s="-1" rad="-1")"},
    {"N.s/m", R"(kg="1" s="-1")"},
};

std::string number(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

}  // namespace

int main(int argc, char** argv) {
    using companion::Causality;
    const companion::Model& m = companion::model();
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"" << m.name << "\" guid=\"" << m.guid
      << "\"\n  description=\"" << m.description
      << "\"\n  generationTool=\"ContactBody system_fmus\" variableNamingConvention=\"flat\" "
         "numberOfEventIndicators=\"0\">\n"
      << "  <CoSimulation modelIdentifier=\"" << m.name
      << "\" canHandleVariableCommunicationStepSize=\"true\" canInterpolateInputs=\"true\"\n"
         "    maxOutputDerivativeOrder=\"0\" canGetAndSetFMUstate=\"true\" "
         "canSerializeFMUstate=\"true\" canNotUseMemoryManagementFunctions=\"true\"/>\n"
      << "  <UnitDefinitions>\n";
    std::map<std::string, bool> used;
    for (const auto& v : m.variables) used[v.unit] = true;
    for (const auto& [unit, _] : used) {
        const auto it = units.find(unit);
        if (it == units.end()) {
            std::cerr << "unit " << unit << " has no base-unit definition\n";
            return 1;
        }
        x << "    <Unit name=\"" << unit << "\"><BaseUnit " << it->second << "/></Unit>\n";
    }
    x << "  </UnitDefinitions>\n"
      << "  <DefaultExperiment startTime=\"0\" stopTime=\"0.02\" stepSize=\"1e-4\"/>\n"
      << "  <ModelVariables>\n";
    for (size_t i = 0; i < m.variables.size(); ++i) {
        const auto& v = m.variables[i];
        if (v.value_reference != i) {
            std::cerr << v.name << ": value reference must equal its position\n";
            return 1;
        }
        x << "    <ScalarVariable name=\"" << v.name << "\" valueReference=\"" << i << "\"";
        switch (v.causality) {
            case Causality::parameter:
                x << " causality=\"parameter\" variability=\"fixed\" initial=\"exact\"";
                break;
            case Causality::input:
                x << " causality=\"input\" variability=\"continuous\"";
                break;
            case Causality::output:
                x << " causality=\"output\" variability=\"continuous\" initial=\"calculated\"";
                break;
        }
        x << "\n      description=\"" << v.description << "\">\n      <Real unit=\"" << v.unit << "\"";
        if (v.causality != Causality::output) x << " start=\"" << number(v.start) << "\"";
        x << "/>\n    </ScalarVariable>\n";
    }
    x << "  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n";
    for (size_t i = 0; i < m.variables.size(); ++i)
        if (m.variables[i].causality == Causality::output)
            x << "      <Unknown index=\"" << i + 1 << "\"/>\n";
    x << "    </Outputs>\n    <InitialUnknowns>\n";
    for (size_t i = 0; i < m.variables.size(); ++i)
        if (m.variables[i].causality == Causality::output)
            x << "      <Unknown index=\"" << i + 1 << "\"/>\n";
    x << "    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n";
    if (argc < 2) {
        std::cout << x.str();
        return 0;
    }
    std::ofstream(argv[1]) << x.str();
    return 0;
}
