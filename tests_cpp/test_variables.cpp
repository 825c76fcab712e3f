// The variable table as the one declaration: what it derives, and that a
// row or field missing from it is refused.
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <type_traits>

#include "variables.hpp"

using namespace contactbody;
using namespace contactbody::fmu;

namespace {

const Variable& named(const char* name) {
    const Variable* v = find_variable(std::string(name));
    EXPECT_NE(v, nullptr) << name;
    return *v;
}

}  // namespace

TEST(Variables, TableIsConsistent) { EXPECT_NO_THROW(check_variable_table(variables())); }

TEST(Variables, ParameterReachingNoSolverFieldIsRefused) {
    std::vector<Variable> rows = variables();
    Variable extra = named("top_mass");
    extra.name = "plate_stiffness";
    extra.value_reference = 999;
    rows.push_back(extra);
    EXPECT_THROW(check_variable_table(rows), std::logic_error);
    rows.back().fmu_only = true;  // declared as the FMU layer's own: accepted
    EXPECT_NO_THROW(check_variable_table(rows));
}

TEST(Variables, SolverFieldWithoutParameterIsRefused) {
    std::vector<Variable> rows;
    for (const Variable& v : variables())
        if (std::strcmp(v.name, "initial_gap") != 0) rows.push_back(v);
    EXPECT_THROW(check_variable_table(rows), std::logic_error);
}

TEST(Variables, ObservableWithoutOutputIsRefused) {
    std::vector<Variable> rows;
    for (const Variable& v : variables())
        if (std::strcmp(v.name, "top_velocity") != 0) rows.push_back(v);
    EXPECT_THROW(check_variable_table(rows), std::logic_error);
}

TEST(Variables, RepeatedValueReferenceIsRefused) {
    std::vector<Variable> rows = variables();
    rows[1].value_reference = rows[0].value_reference;
    EXPECT_THROW(check_variable_table(rows), std::logic_error);
}

// Every SceneParameters field takes its parameter's value: set each parameter to a value
// other than its start and find it in scene().
TEST(Variables, SceneTakesEveryParameter) {
    Values values = start_values();
    const SceneParameters defaults = values.scene();
    for (const Variable& v : variables()) {
        if (v.causality != Causality::parameter || v.fmu_only) continue;
        if (v.real) v.real(values) = v.start + 1;
        else if (v.string) v.string(values) += "mesh.msh";
        else if (v.type == Type::Enumeration) v.integer(values) = v.start == 0 ? 1 : 0;
        else v.integer(values) = static_cast<int>(v.start) + 1;
    }
    const SceneParameters changed = values.scene();
    int fields = 0;
    SceneParameters::for_each(
        [&](const char* name, Reuse, const auto& before, const auto& after) {
            ++fields;
            EXPECT_FALSE(before == after) << name << " does not follow its parameter";
        },
        defaults, changed);
    EXPECT_GE(fields, 25);
}

// Outputs read the Observables field of their name; the table's types follow the fields'.
TEST(Variables, OutputsReadTheirObservable) {
    Values values = start_values();
    double x = 1;
    int n = 1;
    Observables::for_each(
        [&](const char*, auto& field) {
            if constexpr (std::is_same_v<std::decay_t<decltype(field)>, int>) field = n++;
            else field = x++;
        },
        values.out);
    std::set<double> seen;
    int outputs = 0;
    for (const Variable& v : variables()) {
        if (v.causality != Causality::output || v.is_array()) continue;
        ++outputs;
        seen.insert(v.real ? v.real(values) : 1000 + v.integer(values));
    }
    EXPECT_EQ(static_cast<int>(seen.size()), outputs);  // each output its own field
    EXPECT_EQ(outputs, static_cast<int>(x - 1) + (n - 1));
}

// A parameter marked as keeping the discretization does not change it; every other one does.
TEST(Variables, SameDiscretizationFollowsTheDeclaration) {
    const SceneParameters base;
    SceneParameters other = base;
    int rebuilding = 0, keeping = 0;
    SceneParameters::for_each(
        [&](const char* name, Reuse reuse, auto& mine) {
            using Field = std::decay_t<decltype(mine)>;
            const Field kept = mine;
            if constexpr (std::is_same_v<Field, bool>) mine = !mine;
            else if constexpr (std::is_enum_v<Field>) mine = static_cast<Field>(static_cast<int>(mine) == 0 ? 1 : 0);
            else if constexpr (std::is_same_v<Field, std::string>) mine = mine + "other.msh";
            else mine = mine + 1;
            const bool expected_same = reuse == Reuse::keeps_discretization;
            EXPECT_EQ(same_discretization(base, other), expected_same) << name;
            (expected_same ? keeping : rebuilding)++;
            mine = kept;
        },
        other);
    EXPECT_EQ(rebuilding, 15);  // mesh ... top_mass: what discretize reads; modes, reduced_edge: the basis
    EXPECT_GE(keeping, 13);
}

TEST(Variables, InputsInStepOrderAndTunableRetunes) {
    EXPECT_EQ(input_index(named("foundation_velocity")), 0);
    EXPECT_EQ(input_index(named("top_displacement")), 1);
    EXPECT_EQ(input_index(named("top_force")), 2);
    EXPECT_EQ(input_index(named("energy")), -1);
    for (const Variable& v : variables())
        EXPECT_EQ(v.variability == Variability::tunable, v.tune != nullptr) << v.name;
    Values values = start_values();
    named("nx").integer(values) = 7;
    named("nx").after_set(values, "");
    EXPECT_EQ(values.edge_nodes, 8);
    // A mesh sets it to its contact nodes (one that cannot be read leaves it; initialization
    // refuses the file); back to the rectangle, nx + 1 again, and nx no longer moves it.
    named("mesh").string(values) = "no such file.msh";
    named("mesh").after_set(values, "/nowhere/");
    EXPECT_EQ(values.edge_nodes, 8);
    named("mesh").string(values) = "";
    named("mesh").after_set(values, "");
    EXPECT_EQ(values.edge_nodes, 8);
}
