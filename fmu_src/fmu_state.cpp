#include "fmu_state.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "fmi_states.hpp"

namespace contactbody::fmu {

namespace {

constexpr size_t tangents = model_dimension - 1;  // the edge's friction and slip velocities

// Each model's own: a ContactBody state is refused by ContactBody3D, and the reverse.
constexpr char magic[8] = {'C', 'B', solid_model ? '3' : 'F', solid_model ? 'D' : 'M', 'U', 'S', 'T', '\0'};
constexpr size_t header_size = sizeof(magic) + 4 + 8 + 8;  // magic, version, size, checksum
constexpr unsigned restorable_states =
    Instantiated | InitializationMode | StepComplete | StepFailed | Terminated;

// The variables whose values are part of Values (every one but the edge arrays).
size_t stored_variables() {
    size_t n = 0;
    for (const Variable& v : variables()) n += !v.is_array();
    return n;
}

uint64_t fnv1a(const char* data, size_t size) {
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < size; ++i) {
        h ^= static_cast<unsigned char>(data[i]);
        h *= 1099511628211ull;
    }
    return h;
}

// The observables' fields in Observables::for_each's order, for writing and reading.
template <class O, class F>
void visit(O& o, F&& f) {
    Observables::for_each([&](const char*, auto& x) { f(x); }, o);
}

class Writer {
public:
    template <class T>
    void value(const T& x) {
        const char* p = reinterpret_cast<const char*>(&x);
        bytes.insert(bytes.end(), p, p + sizeof(T));
    }
    void string(const std::string& s) {
        value<uint64_t>(s.size());
        bytes.insert(bytes.end(), s.begin(), s.end());
    }
    void doubles(const std::vector<double>& v) {
        value<uint64_t>(v.size());
        const char* p = reinterpret_cast<const char*>(v.data());
        bytes.insert(bytes.end(), p, p + sizeof(double) * v.size());
    }
    void vector(const Eigen::VectorXd& v) {
        value<uint64_t>(static_cast<uint64_t>(v.size()));
        const char* p = reinterpret_cast<const char*>(v.data());
        bytes.insert(bytes.end(), p, p + sizeof(double) * v.size());
    }
    std::vector<char> bytes;
};

class Reader {
public:
    Reader(const char* data, size_t size) : data_(data), size_(size) {}

    template <class T>
    T value(const char* what) {
        need(sizeof(T), what);
        T x;
        std::memcpy(&x, data_ + offset_, sizeof(T));
        offset_ += sizeof(T);
        return x;
    }
    double finite(const char* what) {
        const double x = value<double>(what);
        if (!std::isfinite(x)) fail(std::string(what) + " is not finite");
        return x;
    }
    // A vector of `expected` (or `alternative`) entries.
    Eigen::VectorXd vector(const char* what, Eigen::Index expected, Eigen::Index alternative = -1) {
        const uint64_t n = value<uint64_t>(what);
        if (n != static_cast<uint64_t>(expected) && n != static_cast<uint64_t>(alternative))
            fail(std::string(what) + " has " + std::to_string(n) + " entries, the mesh needs " +
                 std::to_string(expected));
        return doubles_of(n, what);
    }
    // The reduced body's coordinates, or a mesh file's dofs: their count depends on the basis
    // or the file, which the body checks on restore (Body::fits); here only a bound.
    Eigen::VectorXd vector_up_to(const char* what, Eigen::Index limit) {
        const uint64_t n = value<uint64_t>(what);
        if (n < 2 || n > static_cast<uint64_t>(limit))
            fail(std::string(what) + " has " + std::to_string(n) + " entries, between 2 and " +
                 std::to_string(limit) + " expected");
        return doubles_of(n, what);
    }
    Eigen::VectorXd doubles_of(uint64_t n, const char* what) {
        need_doubles(n, what);
        Eigen::VectorXd v(static_cast<Eigen::Index>(n));
        std::memcpy(v.data(), data_ + offset_, n * sizeof(double));
        offset_ += n * sizeof(double);
        if (!v.allFinite()) fail(std::string(what) + " has non-finite entries");
        return v;
    }
    std::string string(const char* what, size_t max_size) {
        const uint64_t n = value<uint64_t>(what);
        if (n > max_size) fail(std::string(what) + " is longer than " + std::to_string(max_size));
        need(n, what);
        std::string s(data_ + offset_, n);
        offset_ += n;
        return s;
    }
    std::vector<double> finite_doubles(const char* what) {
        const uint64_t n = value<uint64_t>(what);
        need_doubles(n, what);  // bounds n before anything is allocated
        std::vector<double> v(n);
        if (n) std::memcpy(v.data(), data_ + offset_, n * sizeof(double));
        offset_ += n * sizeof(double);
        for (double x : v)
            if (!std::isfinite(x)) fail(std::string(what) + " has non-finite entries");
        return v;
    }
    bool at_end() const { return offset_ == size_; }
    [[noreturn]] void fail(const std::string& why) const {
        throw ModelError("FMU state bytes rejected: " + why + " (at byte " +
                         std::to_string(offset_ + header_size) + ")");
    }

private:
    void need(uint64_t n, const char* what) const {
        if (n > size_ - offset_) fail(std::string("truncated while reading ") + what);
    }
    // n doubles, checked without computing n * 8 (which can wrap around).
    void need_doubles(uint64_t n, const char* what) const {
        if (n > (size_ - offset_) / sizeof(double)) fail(std::string("truncated while reading ") + what);
    }
    const char* data_;
    size_t size_, offset_ = 0;
};

}  // namespace

std::vector<char> serialize(const FmuState& s) {
    Writer w;
    w.value<uint32_t>(s.instance_state);
    w.value(s.last_successful_time);
    Values values = s.model.values;
    w.value<uint32_t>(static_cast<uint32_t>(stored_variables()));
    for (const Variable& v : variables()) {
        if (v.is_array()) continue;  // read from the simulation's edge, stored below
        if (v.real)
            w.value(v.real(values));
        else if (v.integer)
            w.value<int32_t>(v.integer(values));
        else
            w.string(v.string(values));
    }
    w.value(s.model.start_time);
    for (double x : s.model.input_rates) w.value(x);
    for (double x : s.model.previous_inputs) w.value(x);
    w.doubles(s.model.field_output_times);
    w.value<uint64_t>(s.model.next_field_output);
    w.value<uint64_t>(s.model.edge_rows);
    w.value<uint64_t>(s.model.next_edge_output);
    w.value<uint8_t>(s.model.has_simulation);
    if (s.model.has_simulation) {
        const SimulationSnapshot& sim = s.model.simulation;
        w.value(sim.state.time);
        w.vector(sim.state.u);
        w.vector(sim.state.v);
        w.vector(sim.state.lambda);
        w.vector(sim.state.sticking);
        Works::for_each(sim.works, sim.works, [&](double x, double) { w.value(x); });
        w.value(sim.initial_energy);
        w.doubles(sim.factor_substeps);
        visit(sim.observables, [&](const auto& x) { w.value(x); });
        for (const Eigen::VectorXd* x :
             {&sim.edge.pressure, &sim.edge.friction[0], &sim.edge.slip_velocity[0], &sim.edge.gap})
            w.vector(*x);
        for (size_t t = 1; t < tangents; ++t) {
            w.vector(sim.edge.friction[t]);
            w.vector(sim.edge.slip_velocity[t]);
        }
        w.value<uint64_t>(static_cast<uint64_t>(sim.edge.state.size()));
        for (Eigen::Index i = 0; i < sim.edge.state.size(); ++i) w.value<int8_t>(sim.edge.state[i]);
        w.value(sim.contact_factorization.substep);
        w.value<uint64_t>(static_cast<uint64_t>(sim.contact_factorization.pattern.size()));
        for (signed char x : sim.contact_factorization.pattern) w.value<int8_t>(x);
        w.value<uint64_t>(static_cast<uint64_t>(sim.contact_factorization.slip.size()));
        for (double x : sim.contact_factorization.slip) w.value(x);
        w.value(sim.controlled_substep);
        w.value(sim.declined_savings);
    }

    std::vector<char> out(header_size + w.bytes.size());
    std::memcpy(out.data(), magic, sizeof(magic));
    const uint32_t version = state_format_version;
    const uint64_t size = w.bytes.size(), checksum = fnv1a(w.bytes.data(), w.bytes.size());
    std::memcpy(out.data() + 8, &version, 4);
    std::memcpy(out.data() + 12, &size, 8);
    std::memcpy(out.data() + 20, &checksum, 8);
    std::memcpy(out.data() + header_size, w.bytes.data(), w.bytes.size());
    return out;
}

FmuState deserialize(const char* bytes, size_t size) {
    if (!bytes) throw ModelError("FMU state bytes rejected: NULL");
    if (size < header_size)
        throw ModelError("FMU state bytes rejected: " + std::to_string(size) +
                         " bytes, shorter than the header");
    if (std::memcmp(bytes, magic, sizeof(magic)) != 0)
        throw ModelError(std::string("FMU state bytes rejected: not a ") + model_identifier +
                         " state (wrong magic)");
    uint32_t version;
    uint64_t payload_size, checksum;
    std::memcpy(&version, bytes + 8, 4);
    std::memcpy(&payload_size, bytes + 12, 8);
    std::memcpy(&checksum, bytes + 20, 8);
    if (version != state_format_version)
        throw ModelError("FMU state bytes rejected: format version " + std::to_string(version) +
                         ", this FMU reads version " + std::to_string(state_format_version));
    if (payload_size != size - header_size)
        throw ModelError("FMU state bytes rejected: header says " + std::to_string(payload_size) +
                         " payload bytes, got " + std::to_string(size - header_size));
    const char* payload = bytes + header_size;
    if (fnv1a(payload, payload_size) != checksum)
        throw ModelError("FMU state bytes rejected: checksum mismatch (corrupted)");

    Reader r(payload, payload_size);
    FmuState s;
    // Every field the table does not read keeps its start (the other model's: the 2D model's
    // foundation velocity and initial velocity along z stay 0).
    s.model.values = start_values();
    s.instance_state = r.value<uint32_t>("instance state");
    if (!(s.instance_state & restorable_states) || (s.instance_state & (s.instance_state - 1)))
        r.fail("invalid instance state " + std::to_string(s.instance_state));
    s.last_successful_time = r.finite("last successful time");
    if (r.value<uint32_t>("variable count") != stored_variables())
        r.fail("variable count differs from this FMU's");
    Values& values = s.model.values;
    for (const Variable& v : variables()) {
        if (v.is_array()) continue;
        if (v.string) {
            v.string(values) = r.string(v.name, max_string_length);
            try {
                check_string(v, v.string(values).c_str());
                if (v.string(values).size() != std::strlen(v.string(values).c_str()))
                    throw std::invalid_argument(std::string(v.name) + " contains a NUL byte");
            } catch (const std::invalid_argument& e) {
                r.fail(e.what());
            }
            continue;
        }
        if (v.real) {
            v.real(values) = r.value<double>(v.name);
        } else {
            v.integer(values) = r.value<int32_t>(v.name);
        }
        if (v.causality == Causality::output) continue;
        try {
            check_range(v, v.real ? v.real(values) : v.integer(values));
        } catch (const std::invalid_argument& e) {
            r.fail(e.what());
        }
    }
    if (!solid_model && values.mesh.empty() && values.edge_nodes != values.nx + 1)
        r.fail("edge_nodes is not nx + 1");
    s.model.start_time = r.finite("start time");
    for (double& x : s.model.input_rates) x = r.finite("input derivative");
    for (double& x : s.model.previous_inputs) x = r.finite("input at the last communication point");
    s.model.field_output_times = r.finite_doubles("field output times");
    s.model.next_field_output = r.value<uint64_t>("next field output");
    if (s.model.next_field_output < s.model.field_output_times.size())
        r.fail("next field output index is below the number of files written");
    s.model.edge_rows = r.value<uint64_t>("edge history records");
    s.model.next_edge_output = r.value<uint64_t>("next edge output");
    if (s.model.next_edge_output < s.model.edge_rows)
        r.fail("next edge output index is below the number of records written");
    const uint8_t has_simulation = r.value<uint8_t>("simulation flag");
    if (has_simulation > 1) r.fail("invalid simulation flag");
    s.model.has_simulation = has_simulation;
    if (has_simulation) {
        try {
            check_parameters(values.scene());
        } catch (const std::invalid_argument& e) {
            r.fail(e.what());
        }
        // The rectangle's dofs; a mesh's are known once it is read (Body::fits checks them on
        // restore). Its contact nodes are edge_nodes, checked at initialization.
        const Eigen::Index dofs = values.mesh.empty()
                                      ? 2 * static_cast<Eigen::Index>(values.nx + 1) * (values.ny + 1)
                                      : model_dimension * static_cast<Eigen::Index>(max_nodes);
        const Eigen::Index nc = values.edge_nodes;
        SimulationSnapshot& sim = s.model.simulation;
        sim.state.time = r.finite("time");
        // Every dof of the full body, or the reduced body's coordinates (its u, v: State).
        if (values.modes == 0 && !values.mesh.empty()) {
            sim.state.u = r.vector_up_to("displacement", dofs);
            sim.state.v = r.vector("velocity", sim.state.u.size());
        } else if (values.modes == 0) {
            sim.state.u = r.vector("displacement", dofs);
            sim.state.v = r.vector("velocity", dofs);
        } else {
            sim.state.u = r.vector_up_to("reduced coordinates", dofs);
            sim.state.v = r.vector("reduced rates", sim.state.u.size());
        }
        sim.state.lambda = r.vector("multipliers", nc, model_dimension * nc);  // dim n_c with friction
        sim.state.sticking = r.vector("sticking nodes", nc);
        Works::for_each(sim.works, sim.works, [&](double& x, double) { x = r.finite("work"); });
        sim.initial_energy = r.finite("initial energy");
        if (sim.initial_energy < 0) r.fail("initial energy is negative");
        sim.factor_substeps = r.finite_doubles("cached substep sizes");
        if (sim.factor_substeps.size() > Stepper::factor_cache_size)  // the reduced body's too
            r.fail("more cached substep sizes than the factor cache holds");
        for (double dt : sim.factor_substeps)
            if (!(dt > 0)) r.fail("cached substep sizes must be > 0");
        visit(sim.observables, [&](auto& x) {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, double>)
                x = r.finite("observable");
            else
                x = r.value<int32_t>("observable");
        });
        EdgeSnapshot& edge = sim.edge;
        edge.pressure = r.vector("edge pressure", nc);
        edge.friction[0] = r.vector("edge friction", nc);
        edge.slip_velocity[0] = r.vector("edge slip velocity", nc);
        edge.gap = r.vector("edge gap", nc);
        for (size_t t = 1; t < tangents; ++t) {
            edge.friction[t] = r.vector("edge friction z", nc);
            edge.slip_velocity[t] = r.vector("edge slip velocity z", nc);
        }
        if (r.value<uint64_t>("edge states") != static_cast<uint64_t>(nc))
            r.fail("edge states do not fit the mesh");
        edge.state.resize(nc);
        for (Eigen::Index i = 0; i < nc; ++i) {
            edge.state[i] = r.value<int8_t>("edge state");
            if (edge.state[i] < 0 || edge.state[i] > 2) r.fail("invalid edge state");
        }
        ContactFactorization& f = sim.contact_factorization;
        f.substep = r.finite("contact factorization substep");
        if (f.substep < 0) r.fail("contact factorization substep is negative");
        const uint64_t pattern = r.value<uint64_t>("contact factorization size");
        if (pattern != 0 && pattern != static_cast<uint64_t>(nc))
            r.fail("contact factorization does not fit the mesh");
        f.pattern.resize(static_cast<size_t>(pattern));
        for (signed char& x : f.pattern) {
            x = r.value<int8_t>("contact factorization node state");
            if (x != 0 && x != 1 && x != 2 && x != -2 && x != 3 && x != -3)
                r.fail("invalid contact factorization node state");
        }
        const uint64_t slips = r.value<uint64_t>("contact factorization slips");
        if (slips != 0 && (pattern == 0 || slips % pattern != 0 || slips / pattern != tangents))
            r.fail("contact factorization slips do not fit the mesh");
        f.slip.resize(static_cast<size_t>(slips));
        for (double& x : f.slip) {
            x = r.finite("contact factorization slip");
            if (std::abs(x) > 1) r.fail("invalid contact factorization slip");
        }
        for (size_t k = 0; k < f.slip.size(); ++k)
            if (f.slip[k] != 0 && f.pattern[k % f.pattern.size()] != 3)
                r.fail("a contact factorization slip at a node that holds none");
        sim.controlled_substep = r.finite("the controller's substep");
        if (sim.controlled_substep < 0) r.fail("the controller's substep is negative");
        sim.declined_savings = r.finite("the controller's declined savings");
        if (sim.declined_savings < 0) r.fail("the controller's declined savings are negative");
    }
    if (!r.at_end()) r.fail("trailing bytes after the state");
    return s;
}

}  // namespace contactbody::fmu
