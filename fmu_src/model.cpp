#include "model.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/gmsh.hpp"
#include "util/c_file.hpp"
#include "util/text.hpp"

namespace contactbody::fmu {

namespace {

template <class... Parts>
std::string concat(const Parts&... parts) {
    Text s;
    s.precision(17);
    (s << ... << parts);
    return s.str();
}

// Runs f, reporting std::invalid_argument (a bad value) as ModelError.
template <class F>
void as_model_error(F&& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        throw ModelError(e.what());
    }
}

}  // namespace

void ContactBodyModel::set_defaults(const std::vector<std::pair<std::string, std::string>>& values) {
    for (const auto& [name, text] : values) {
        const Variable* v = find_variable(name);
        if (!v || v->causality == Causality::output)
            throw ModelError(
                concat("resources/start_values.txt: ", name, " is not a parameter or input of this FMU"));
        if (v->string) {
            set_string(*v, text.c_str(), false);
            continue;
        }
        double x = 0;
        if (!parse_number(text, x))
            throw ModelError(concat("resources/start_values.txt: ", name, " = '", text, "' is not a number"));
        if (v->real)
            set_real(*v, x, false);
        else if (x != static_cast<int>(x))
            throw ModelError(
                concat("resources/start_values.txt: ", name, " = '", text, "' is not an integer"));
        else
            set_integer(*v, static_cast<int>(x), false);
    }
    defaults_ = values_;
}

void ContactBodyModel::reset() {
    values_ = defaults_;
    fields_.reset();
    rebuild_ = true;  // sim_ stays: the next initialization may reuse its discretization
    start_time_ = 0;
}

void ContactBodyModel::set_start_time(double t) {
    if (!std::isfinite(t)) throw ModelError(concat("start time must be finite (got ", t, ")"));
    start_time_ = t;
    rebuild_ = true;
}

void ContactBodyModel::check_writable(const Variable& v, bool initialized) const {
    if (v.causality == Causality::output)
        throw ModelError(concat("variable ", v.name, " is an output and cannot be set"));
    if (initialized && !v.settable_after_initialization())
        throw ModelError(concat("parameter ", v.name, " is fixed and cannot be set after initialization"));
}

void ContactBodyModel::check_settable(const Variable& v, double value, bool initialized) const {
    check_writable(v, initialized);
    as_model_error([&] { check_range(v, value); });
}

void ContactBodyModel::set_real(const Variable& v, double value, bool initialized) {
    if (!v.real) throw ModelError(concat("variable ", v.name, " is not of type Real"));
    check_settable(v, value, initialized);
    v.real(values_) = value;
    if (input_index(v) >= 0) input_rates_[input_index(v)] = 0;  // a new value is held
    if (v.after_set) v.after_set(values_, resources_);
    if (!initialized) {
        rebuild_ = true;  // parameters and initial inputs define the initial state
    } else if (sim_ && v.tune) {
        v.tune(*sim_, value);
    }
}

void ContactBodyModel::set_integer(const Variable& v, int value, bool initialized) {
    if (!v.integer) throw ModelError(concat("variable ", v.name, " is not of type Integer or Enumeration"));
    check_settable(v, value, initialized);
    v.integer(values_) = value;
    if (v.after_set) v.after_set(values_, resources_);
    if (!initialized) rebuild_ = true;
}

void ContactBodyModel::set_string(const Variable& v, const char* value, bool initialized) {
    if (!v.string) throw ModelError(concat("variable ", v.name, " is not of type String"));
    check_writable(v, initialized);
    as_model_error([&] { check_string(v, value); });
    v.string(values_) = value;
    if (v.after_set) v.after_set(values_, resources_);
    rebuild_ = true;
}

const char* ContactBodyModel::get_string(const Variable& v) {
    if (!v.string) throw ModelError(concat("variable ", v.name, " is not of type String"));
    return v.string(values_).c_str();
}

double ContactBodyModel::get_real(const Variable& v) {
    if (!v.real) throw ModelError(concat("variable ", v.name, " is not of type Real"));
    if (v.causality == Causality::output) refresh_outputs();
    return v.real(values_);
}

int ContactBodyModel::get_integer(const Variable& v) {
    if (!v.integer) throw ModelError(concat("variable ", v.name, " is not of type Integer or Enumeration"));
    if (v.causality == Causality::output) refresh_outputs();
    return v.integer(values_);
}

size_t ContactBodyModel::size(const Variable& v) const {
    return v.is_array() ? static_cast<size_t>(values_.edge_nodes) : 1;
}

void ContactBodyModel::get_edge(const Variable& v, double* out) {
    if (!v.edge_real) throw ModelError(concat("variable ", v.name, " is not a Float64 array"));
    refresh_outputs();
    const Eigen::VectorXd& x = v.edge_real(sim_->edge());
    std::copy(x.data(), x.data() + x.size(), out);
}

void ContactBodyModel::get_edge(const Variable& v, int64_t* out) {
    if (!v.edge_state) throw ModelError(concat("variable ", v.name, " is not an Int64 array"));
    refresh_outputs();
    const auto& state = sim_->edge().state;
    for (Eigen::Index i = 0; i < state.size(); ++i) out[i] = state[i];
}

void ContactBodyModel::set_input_derivative(const Variable& v, int order, double value) {
    if (input_index(v) < 0)
        throw ModelError(concat("variable ", v.name, " is not an input: it has no derivative"));
    if (order != 1)
        throw ModelError(concat("derivative order ", order, " of ", v.name,
                                " is not supported (only 1: linear interpolation)"));
    if (!std::isfinite(value))
        throw ModelError(concat("derivative of ", v.name, " must be finite (got ", value, ")"));
    input_rates_[input_index(v)] = value;
}

// Reuses the last simulation's discretization and factors when the parameters allow (studies
// reset and rerun with other inputs or contact parameters), with the same results as a new one.
void ContactBodyModel::build_simulation(const Values& values) {
    fields_.reset();  // it refers to the old simulation's mesh
    SceneParameters scene = values.scene();
    scene.mesh = mesh_path(scene.mesh, resources_);
    // The foundation's initial speed in its plane (the warnings' sliding speed).
    double sliding_speed = 0;
    for (double v : values.foundation_velocity) sliding_speed += v * v;
    sliding_speed = std::sqrt(sliding_speed);
    try {
        // The same parameters, and a mesh file as it was when the body was built from it.
        if (sim_ && same_discretization(sim_->body().parameters(), scene) &&
            (scene.mesh.empty() ||
             gmsh_file_digest(scene.mesh, max_nodes) == sim_->body().discretization().mesh.file_digest)) {
            sim_->restart(scene, values.top_displacement, start_time_, values.top_force, sliding_speed);
        } else {
            sim_.reset();  // before the new one: never two discretizations in memory
            sim_ = std::make_unique<Simulation>(scene, values.top_displacement, start_time_, values.top_force,
                                                sliding_speed);
        }
    } catch (const std::invalid_argument& e) {
        sim_.reset();
        throw ModelError(e.what());
    } catch (...) {
        sim_.reset();
        throw;
    }
}

// Creates the writer for result_directory (an unwritable directory is an error here, at
// initialization, not in the middle of a run).
void ContactBodyModel::open_field_output() {
    fields_.reset();
    edge_.reset();
    if (values_.edge_output_interval > 0 && values_.result_directory.empty())
        throw ModelError(
            "edge_output_interval > 0 needs a result_directory for the edge "
            "history file");
    if (values_.result_directory.empty()) return;
    try {
        fields_ = std::make_unique<FieldWriter>(sim_->body().discretization().mesh, values_.result_directory);
        if (values_.edge_output_interval > 0)
            edge_ = std::make_unique<EdgeWriter>(join_path(values_.result_directory, "contactbody_edge.npy"),
                                                 sim_->body().num_contact_nodes(),
                                                 sim_->body().discretization().mesh.tangents());
    } catch (const std::exception& e) {
        throw ModelError(e.what());
    }
}

// One record at the first communication point at or after each due output time.
void ContactBodyModel::write_due_edge() {
    const double interval = values_.edge_output_interval;
    const double elapsed = sim_->time() - start_time_;
    if (elapsed < (static_cast<double>(next_edge_output_) - 1e-9) * interval) return;
    try {
        edge_->write(sim_->time(), sim_->edge());
    } catch (const std::exception& e) {
        throw ModelError(concat("edge history failed at t = ", sim_->time(), ": ", e.what()));
    }
    next_edge_output_ = static_cast<uint64_t>(std::floor(elapsed / interval + 1e-9)) + 1;
}

// Writes one file at the first communication point at or after each due output time.
void ContactBodyModel::write_due_fields() {
    const double interval = values_.field_output_interval;
    const double elapsed = sim_->time() - start_time_;
    if (elapsed < (static_cast<double>(next_field_output_) - 1e-9) * interval) return;
    try {
        if (sim_->body().modes() == 0) {
            fields_->write(sim_->state());
        } else {  // the reduced body's field, on every dof
            sim_->full_state(field_state_);
            fields_->write(field_state_);
        }
    } catch (const std::exception& e) {
        throw ModelError(concat("field output failed at t = ", sim_->time(), ": ", e.what()));
    }
    next_field_output_ = static_cast<uint64_t>(std::floor(elapsed / interval + 1e-9)) + 1;
}

void ContactBodyModel::set_resources(std::string folder, bool edge_arrays) {
    if (!folder.empty() && folder.back() != '/' && folder.back() != '\\') folder += '/';
    resources_ = std::move(folder);
    edge_arrays_ = edge_arrays;
}

void ContactBodyModel::check_structure() const {
    if (!solid_model && values_.mesh.empty() && values_.edge_nodes != values_.nx + 1)
        throw ModelError(concat("edge_nodes = ", values_.edge_nodes, " but nx + 1 = ", values_.nx + 1,
                                ": the edge arrays hold one value per bottom node (setting nx "
                                "sets edge_nodes; set edge_nodes only to nx + 1)"));
}

std::array<double, num_inputs> ContactBodyModel::current_inputs() const {
    return {values_.foundation_velocity[0], values_.top_displacement, values_.top_force,
            values_.foundation_velocity[1]};
}

void ContactBodyModel::initialize() {
    if (!rebuild_ && sim_) return;
    check_structure();
    build_simulation(values_);
    if (!values_.mesh.empty()) {
        const int contact_nodes = static_cast<int>(sim_->body().num_contact_nodes());
        if (edge_arrays_ && values_.edge_nodes != contact_nodes) {
            const int given = values_.edge_nodes;
            sim_.reset();
            throw ModelError(concat("edge_nodes = ", given, " but the mesh ", values_.mesh, " has ",
                                    contact_nodes, " contact nodes: set edge_nodes = ", contact_nodes,
                                    " (the size of the edge arrays)"));
        }
        values_.edge_nodes = contact_nodes;
    }
    open_field_output();
    values_.out = Observables{};
    previous_inputs_ = current_inputs();
    rebuild_ = false;
    next_field_output_ = 0;
    next_edge_output_ = 0;
    if (fields_) write_due_fields();  // the initial state
    if (edge_) write_due_edge();
}

ModelState ContactBodyModel::save() const {
    ModelState s;
    s.values = values_;
    s.start_time = start_time_;
    s.input_rates = input_rates_;
    s.previous_inputs = previous_inputs_;
    s.has_simulation = sim_ && !rebuild_;
    if (s.has_simulation) {
        s.simulation = sim_->snapshot();
        // The outputs as they are, not as last read: the bytes do not depend on what was read.
        s.values.out = sim_->observables();
    }
    if (fields_) s.field_output_times = fields_->times();
    s.next_field_output = next_field_output_;
    if (edge_) s.edge_rows = edge_->rows();
    s.next_edge_output = next_edge_output_;
    return s;
}

void ContactBodyModel::load(const ModelState& state) {
    Values saved = state.values;
    if (sim_ && !rebuild_) {
        for (const Variable& v : variables()) {
            if (v.causality != Causality::parameter || v.variability != Variability::fixed) continue;
            if (v.string) {
                if (v.string(values_) != v.string(saved))
                    throw ModelError(concat("the state was saved with ", v.name, " = '", v.string(saved),
                                            "', this instance has '", v.string(values_), "'"));
                continue;
            }
            const double mine = v.real ? v.real(values_) : v.integer(values_);
            const double theirs = v.real ? v.real(saved) : v.integer(saved);
            if (mine != theirs)
                throw ModelError(concat("the state was saved with ", v.name, " = ", theirs,
                                        ", this instance has ", v.name, " = ", mine));
        }
    }
    if (state.has_simulation) {
        if (!sim_ || rebuild_) build_simulation(saved);
        try {
            sim_->restore(state.simulation);
        } catch (const std::invalid_argument& e) {
            throw ModelError(concat("the state does not fit this instance: ", e.what()));
        }
        sim_->set_friction_coefficient(saved.friction_coefficient);
    } else {
        fields_.reset();
        sim_.reset();
    }
    values_ = saved;
    start_time_ = state.start_time;
    input_rates_ = state.input_rates;
    previous_inputs_ = state.previous_inputs;
    rebuild_ = !state.has_simulation;
    next_field_output_ = state.next_field_output;
    next_edge_output_ = state.next_edge_output;
    if (state.has_simulation) {
        // The collection lists what was written up to the saved time: a rolled-back run
        // overwrites the later files as it goes.
        if (!fields_) open_field_output();
        if (fields_) {
            try {
                fields_->set_times(state.field_output_times);
                if (edge_) edge_->truncate(state.edge_rows);
            } catch (const std::exception& e) {
                throw ModelError(e.what());
            }
        }
    }
}

void ContactBodyModel::refresh_outputs() {
    initialize();  // outputs read in initialization mode come from the initial state
    const Observables& o = sim_->observables();
    values_.out = o;
}

double ContactBodyModel::time() const { return sim_ && !rebuild_ ? sim_->time() : start_time_; }

void ContactBodyModel::do_step(double current_time, double h) {
    if (!sim_ || rebuild_) throw ModelError("the model is not initialized");
    if (!(std::isfinite(h) && h > 0))
        throw ModelError(concat("communicationStepSize must be finite and > 0 (got ", h, ")"));
    const double t = sim_->time();
    if (!std::isfinite(current_time) ||
        std::abs(current_time - t) > 1e-9 * std::max(1.0, std::abs(t)) + 1e-12)
        throw ModelError(
            concat("currentCommunicationPoint ", current_time, " does not match the FMU's time ", t));
    // Each input's value at the step's start and its rate across the step: the derivative the
    // master set, or with input_interpolation = ramp and no derivative, the line from the
    // value at the previous communication point to the one set now.
    const std::array<double*, num_inputs> value = {&values_.foundation_velocity[0], &values_.top_displacement,
                                                   &values_.top_force, &values_.foundation_velocity[1]};
    std::array<double, num_inputs> start{}, rate{};
    const bool ramp = values_.input_interpolation == static_cast<int>(InputInterpolation::ramp);
    for (int i = 0; i < num_inputs; ++i) {
        const bool ramped = ramp && input_rates_[i] == 0;
        start[i] = ramped ? previous_inputs_[i] : *value[i];
        rate[i] = ramped ? (*value[i] - previous_inputs_[i]) / h : input_rates_[i];
    }
    StepInputs in;
    in.foundation_velocity = {start[0], start[3]};  // the tangents' slots (Input)
    in.foundation_acceleration = {rate[0], rate[3]};
    in.top_displacement = start[1];
    in.top_velocity = rate[1];
    in.top_force = start[2];
    in.top_force_rate = rate[2];
    try {
        sim_->do_step(h, in);
        // Interpolated inputs go on along their line until the master sets them again.
        for (int i = 0; i < num_inputs; ++i) *value[i] += input_rates_[i] * h;
        previous_inputs_ = current_inputs();
        if (fields_) write_due_fields();
        if (edge_) write_due_edge();
    } catch (const NumericalFailure& e) {
        throw StepError(concat("step from t = ", t, " failed, state restored to its start: ", e.what()));
    } catch (const std::invalid_argument& e) {
        throw ModelError(e.what());
    }
}

}  // namespace contactbody::fmu
