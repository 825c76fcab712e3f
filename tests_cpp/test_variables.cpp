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

TEST(Variables, TableIsConsistent) { EXPECT_NO_THROW(check_variable_table(all_model_variables())); }

// The two models' tables: this binary's is the 2D one (ContactBody). The 3D rows are the z
// outputs and input, initial_velocity_z and the 3D mesh's; the rectangle is the 2D model's.
TEST(Variables, EachModelHasItsRows) {
    std::set<std::string> planar, solid;
    for (const Variable& v : all_model_variables()) {
        if (v.dimension != 3) planar.insert(v.name);
        if (v.dimension != 2) solid.insert(v.name);
    }
    for (const char* name : {"width", "height", "nx", "ny"}) {
        EXPECT_TRUE(planar.count(name)) << name;
        EXPECT_FALSE(solid.count(name)) << name;
    }
    for (const char* name : {"foundation_velocity_z", "initial_velocity_z", "friction_force_z",
                             "top_reaction_z", "edge_z", "edge_friction_z", "edge_slip_velocity_z"}) {
        EXPECT_FALSE(planar.count(name)) << name;
        EXPECT_TRUE(solid.count(name)) << name;
    }
    EXPECT_EQ(model_dimension, 2);
    EXPECT_EQ(variables().size(), planar.size());
    // A row repeated in one model is refused.
    std::vector<Variable> rows = all_model_variables();
    rows.push_back(rows.front());
    rows.back().value_reference = 9999;
    EXPECT_THROW(check_variable_table(rows), std::logic_error);
}

TEST(Variables, ParameterReachingNoSolverFieldIsRefused) {
    std::vector<Variable> rows = all_model_variables();
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
    for (const Variable& v : all_model_variables())
        if (std::strcmp(v.name, "initial_gap") != 0) rows.push_back(v);
    EXPECT_THROW(check_variable_table(rows), std::logic_error);
}

TEST(Variables, ObservableWithoutOutputIsRefused) {
    std::vector<Variable> rows;
    for (const Variable& v : all_model_variables())
        if (std::strcmp(v.name, "top_velocity") != 0) rows.push_back(v);
    EXPECT_THROW(check_variable_table(rows), std::logic_error);
}

TEST(Variables, RepeatedValueReferenceIsRefused) {
    std::vector<Variable> rows = all_model_variables();
    rows[2].value_reference = rows[0].value_reference;  // width takes the 2D mesh's
    EXPECT_THROW(check_variable_table(rows), std::logic_error);
}

// Every SceneParameters field takes its parameter's value: set each parameter to a value
// other than its start and find it in scene().
TEST(Variables, SceneTakesEveryParameter) {
    Values values = start_values();
    const SceneParameters defaults = values.scene();
    for (const Variable& v : variables()) {
        if (v.causality != Causality::parameter || v.fmu_only) continue;
        if (v.real)
            v.real(values) = v.start + 1;
        else if (v.string)
            v.string(values) += "mesh.msh";
        else if (v.type == Type::Enumeration)
            v.integer(values) = v.start == 0 ? 1 : 0;
        else
            v.integer(values) = static_cast<int>(v.start) + 1;
    }
    const SceneParameters changed = values.scene();
    int fields = 0;
    SceneParameters::for_each(
        [&](const char* name, Reuse, const auto& before, const auto& after) {
            if (!find_variable(name)) return;  // the other model's (initial_velocity_z)
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
        [&](const char* name, auto& field) {
            if (!find_variable(name)) return;  // the other model's (the z components)
            if constexpr (std::is_same_v<std::decay_t<decltype(field)>, int>)
                field = n++;
            else
                field = x++;
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
            if constexpr (std::is_same_v<Field, bool>)
                mine = !mine;
            else if constexpr (std::is_enum_v<Field>)
                mine = static_cast<Field>(static_cast<int>(mine) == 0 ? 1 : 0);
            else if constexpr (std::is_same_v<Field, std::string>)
                mine = mine + "other.msh";
            else
                mine = mine + 1;
            const bool expected_same = reuse == Reuse::keeps_discretization;
            EXPECT_EQ(same_discretization(base, other), expected_same) << name;
            (expected_same ? keeping : rebuilding)++;
            mine = kept;
        },
        other);
    EXPECT_EQ(rebuilding, 17);  // mesh ... top_mass: what discretize reads; modes, reduced_edge: the basis;
                                // baseline_kernels, threads: the factors
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
