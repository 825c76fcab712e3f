#include "body/stepper.hpp"

#include "linalg/trailing_cholesky.hpp"
#include "util/text.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace contactbody {

namespace {

// Adds the time since the last lap to one of the timings (no cost when timing is off).
class Laps {
public:
    explicit Laps(bool on) : on_(on) {
        if (on_) last_ = std::chrono::steady_clock::now();
    }
    void lap(double& into) {
        if (!on_) return;
        const auto now = std::chrono::steady_clock::now();
        into += std::chrono::duration<double>(now - last_).count();
        last_ = now;
    }

private:
    bool on_;
    std::chrono::steady_clock::time_point last_;
};

}  // namespace

// Factor of K = 4/dt^2 M + A on the free dofs with the contact dofs ordered last, and the
// contact operators that live on its trailing block L22 (m = 2 n_c unknowns, N then T):
//   G = L22^-1 S with S the signed placement of B^T's columns,  W = B K^-1 B^T = G^T G.
// Then with y = L^-1 P rhs:  B K^-1 rhs = G^T y_2, and adding B^T lambda to the right-hand
// side only adds G lambda to y_2, so a substep is one forward and one backward solve.
struct Stepper::Factor {
    double dt = 0;
    int id = 0;  // the factorization's number: W is rebuilt when another factor is used
    std::unique_ptr<TrailingCholesky> cholesky;
    Eigen::MatrixXd G;            // trailing positions x (N, T)
    Eigen::MatrixXd delassus;     // G^T G, (N, T) x (N, T)
    SparseMatrix K_free_clamped;  // the coupling of free and clamped dofs in K
    // The sparse contact solve's operator instead of cholesky, G and delassus (wants_sparse).
    std::unique_ptr<HeldOperator> held;
};

namespace {

// Eigen sizes the blocks of its dense products (the Delassus operator G^T G, the triangular
// solve for G, the blocked LU of the contact Newton systems) by the CPU's caches, read at run
// time, and the blocks decide the order of the sums: the same binary computed other bits on a
// CPU with a 48 KiB L1 (AMD EPYC) than with 32 KiB, from about 100 contact nodes on. Fixed
// sizes (a common x86 server's) make every machine compute the same bits
// (python_tests/test_portable.py compares with a recorded run). Eigen is compiled into this
// library with hidden symbols, so the setting stays ours.
void fix_dense_blocking() {
    static std::once_flag once;
    std::call_once(once, [] { Eigen::setCpuCacheSizes(32 << 10, 1 << 20, 32 << 20); });
}

}  // namespace

Stepper::Stepper(const SceneParameters& params) : params_(params), disc_(discretize(params)) {
    fix_dense_blocking();
    start_run();
}

void Stepper::start_run() {
    options_ = ContactSolverOptions{};
    options_.tolerance = params_.contact_tolerance;
    solver_ = ContactSolver{};
    sparse_solver_ = SparseContactSolver{};
    problem_ = ContactProblem{};
    snapshot_ = ContactSnapshot{};
    timing_ = false;
    timings_ = SubstepTimings{};
    problem_factor_ = 0;
    current_factor_ = 0;
    const Eigen::Index nf = disc_.expand.cols();
    const Eigen::Index nc = num_contact_nodes();
    relative_.resize(disc_.mesh.num_dofs());
    product_.resize(disc_.mesh.num_dofs());
    w_.resize(disc_.mesh.num_dofs());
    du_.resize(disc_.mesh.num_dofs());
    C_du_.resize(disc_.mesh.num_dofs());
    rhs_.resize(nf);
    w_free_.resize(nf);
    // The unknowns a translation along y moves (the plate's too), and M of that translation.
    normal_free_.setZero(nf);
    for (int dof : disc_.free_dofs)
        if (disc_.mesh.component(dof) == Mesh::normal) normal_free_[disc_.free_index[dof]] = 1;
    if (disc_.plate_index >= 0) normal_free_[disc_.plate_index] = 1;
    normal_mass_.noalias() = disc_.M_free_rows * (disc_.expand * normal_free_);
    clamped_half_.resize(static_cast<Eigen::Index>(disc_.clamped_dofs.size()));
    problem_.tangents = disc_.mesh.dim - 1;
    problem_.a.resize(disc_.mesh.dim * nc);
    problem_.gap_limit.resize(nc);
    problem_.slip_origin.resize(problem_.tangents * nc);
}

void Stepper::restart(const SceneParameters& params) {
    if (!same_discretization(params_, params))
        throw std::logic_error("Stepper::restart: the parameters define another discretization");
    check_parameters(params);
    params_ = params;
    for (auto it = cache_.rbegin(); it != cache_.rend(); ++it)
        if (*it) keep_spare(std::move(*it));
    start_run();
}

Stepper::~Stepper() = default;

std::pair<double, double> Stepper::kinetic_and_strain_energy(const State& s) {
    product_.noalias() = disc_.M * s.v;
    double kinetic = 0.5 * s.v.dot(product_);
    if (disc_.plate_index >= 0) {  // the plate's own: 1/2 m_p v_top^2
        const double v = s.v[disc_.top_y_dof()];
        kinetic += 0.5 * disc_.plate_mass * v * v;
    }
    return {kinetic, disc_.strain_energy(s.u)};
}

bool Stepper::set_clamp(State& s, double top, double rate) const {
    const std::vector<int>& nodes = disc_.mesh.top_nodes;
    const bool moves = std::any_of(nodes.begin(), nodes.end(), [&](int n) {
        const int y = disc_.mesh.dof(n, Mesh::normal);
        return s.u[y] != top || s.v[y] != rate;
    });
    for (int node : nodes) {
        s.u[disc_.mesh.dof(node, Mesh::normal)] = top;
        s.v[disc_.mesh.dof(node, Mesh::normal)] = rate;
    }
    return moves;
}

bool Stepper::fits(const State& s) const {
    const Eigen::Index dofs = disc_.mesh.num_dofs(), nc = num_contact_nodes();
    return s.u.size() == dofs && s.v.size() == dofs &&
           (s.lambda.size() == nc || s.lambda.size() == disc_.mesh.dim * nc) && s.sticking.size() == nc;
}

State Stepper::initial_state(double top_displacement) const {
    return paper_initial_state(disc_, params_, top_displacement);
}

State Stepper::paper_initial_state(const Discretization& d, const SceneParameters& p,
                                   double top_displacement) {
    State s;
    const Mesh& mesh = d.mesh;
    s.u.setZero(mesh.num_dofs());
    s.v.setZero(mesh.num_dofs());
    // u_y grows linearly from the contact to the clamp's highest node, and no further: a body
    // reaching above its clamp moves rigidly with it there.
    for (int n = 0; n < mesh.num_nodes(); ++n) {
        const double height = std::clamp(mesh.point(n).y - mesh.contact_y, 0.0, mesh.clamp_height());
        s.u[mesh.dof(n, Mesh::normal)] = top_displacement * height / mesh.clamp_height();
    }
    // The clamp starts where it is driven, at every height it spans (a side face too): the
    // first substep would otherwise move it there at once, with work no one counts.
    for (int n : mesh.top_nodes) s.u[mesh.dof(n, Mesh::normal)] = top_displacement;
    for (int dof : d.moving_dofs) s.v[dof] = p.initial_velocity[static_cast<size_t>(mesh.component(dof))];
    const Eigen::Index nc = static_cast<Eigen::Index>(d.contact_tangential[0].size());
    s.lambda.setZero(p.friction_coefficient > 0 ? mesh.dim * nc : nc);  // N, then x (and z)
    s.sticking.setZero(nc);
    return s;
}

void Stepper::set_friction_coefficient(double friction) {
    // A held operator has a second tangent's contact dofs with friction, not without: a factor
    // made for the other is dropped.
    if (held_unknowns_per_node(friction) != held_unknowns_per_node(params_.friction_coefficient)) {
        for (auto& f : cache_) f.reset();
        spare_.clear();
    }
    params_.friction_coefficient = friction;
    problem_factor_ = 0;  // the problem's size may change: rebuild W on next use
    for (auto& f : cache_)
        if (f && f->held) f->held->set_slip_coefficient(slip_coefficient());
}

double Stepper::slip_coefficient() const {
    return contact_path_ != ContactPath::sparse_gcr ? params_.friction_coefficient : 0.0;
}

int Stepper::held_unknowns_per_node(double friction) const {
    return friction > 0 ? 1 + disc_.mesh.tangents() : 2;
}

int add_node_contact(SubstepReport& report, double& sticking, double lN, double lT, double uN_old, double duN,
                     double dux, double foundation_step, double initial_gap, bool friction, bool touching,
                     NodeStatus status) {
    report.normal_force -= lN;
    report.friction_force[0] += lT;
    report.work.friction += lT * dux;
    report.work.normal_contact += lN * duN;
    report.work.foundation += lT * foundation_step;
    report.work.friction_dissipation += lT * (foundation_step - dux);
    report.max_penetration = std::max(report.max_penetration, duN - (initial_gap - uN_old));
    sticking = friction && touching && status == NodeStatus::stick ? 1.0 : 0.0;
    if (!touching) return 0;
    if (status != NodeStatus::open) {
        ++report.active_nodes;
        if (status == NodeStatus::slip) ++report.slipping_nodes;
    }
    return static_cast<int>(status);
}

Stepper::Factor& Stepper::factor_for(double dt) {
    for (size_t k = 0; k < cache_.size(); ++k) {
        if (cache_[k] && std::abs(cache_[k]->dt - dt) <= 1e-14 * dt) {
            std::rotate(cache_.begin(), cache_.begin() + static_cast<long>(k),
                        cache_.begin() + static_cast<long>(k) + 1);
            return *cache_[0];
        }
    }
    std::rotate(cache_.begin(), cache_.end() - 1, cache_.end());  // the oldest to the front
    if (cache_[0]) keep_spare(std::move(cache_[0]));
    cache_[0] = make_factor(dt);
    return *cache_[0];
}

double Stepper::new_operator_in_solves() const {
    const Factor* f = cache_[0].get();
    if (!f) return 0;
    if (f->held) return f->held->refactorization_in_solves();
    return f->cholesky->factor_flops() / (4 * f->cholesky->factor_nonzeros());
}

void Stepper::keep_spare(std::unique_ptr<Factor> f) {
    spare_.insert(spare_.begin(), std::move(f));
    if (spare_.size() > spare_capacity) spare_.pop_back();
}

std::vector<double> Stepper::cached_substeps() const {
    std::vector<double> sizes;
    for (const auto& f : cache_)
        if (f) sizes.push_back(f->dt);
    return sizes;
}

void Stepper::set_cached_substeps(const std::vector<double>& sizes) {
    if (sizes.size() > cache_.size())
        throw std::invalid_argument("more cached substep sizes than the cache holds");
    std::array<std::unique_ptr<Factor>, factor_cache_size> next;
    for (size_t k = 0; k < sizes.size(); ++k) {
        for (auto& f : cache_)  // a factor of exactly this size is kept, not rebuilt
            if (f && f->dt == sizes[k]) next[k] = std::move(f);
        if (!next[k]) next[k] = make_factor(sizes[k]);
    }
    for (auto& f : cache_)
        if (f) keep_spare(std::move(f));
    cache_ = std::move(next);
    problem_factor_ = 0;
}

bool Stepper::sparse_contact_pays(Eigen::Index contact_nodes, Eigen::Index unknowns, double friction) {
    const double m = 2.0 * static_cast<double>(contact_nodes);
    return m * m > sparse_contact_kappa(friction) * static_cast<double>(unknowns);
}

std::string Stepper::summary() const {
    const double m = 2.0 * num_contact_nodes(), ratio = m * m / static_cast<double>(disc_.expand.cols());
    Text msg;
    msg << "contact solve: " << (wants_sparse() ? "sparse, on the body's system" : "condensed, a dense W")
        << " of the " << num_contact_nodes() << " contact nodes ((2 n_c)^2 / unknowns = " << ratio
        << (contact_path_ != ContactPath::automatic                      ? ", chosen by the caller"
            : rate_law(params_).active()                                 ? ", a slip-rate law: condensed"
            : ratio > sparse_contact_kappa(params_.friction_coefficient) ? " > "
                                                                         : " <= ");
    if (contact_path_ == ContactPath::automatic && !rate_law(params_).active())
        msg << sparse_contact_kappa_0 << " + " << sparse_contact_kappa_F
            << " F = " << sparse_contact_kappa(params_.friction_coefficient);
    msg << ")";
    // (which factors are supernodal is known once they are made)
    if (const char* kernels = TrailingCholesky::supernodal_kernel_set(params_.baseline_kernels))
        msg << "; a supernodal factor's kernels (from " << TrailingCholesky::dense_supernodal_flops << " flops at "
            << TrailingCholesky::dense_flops_per_nonzero << " per factor nonzero, else "
            << TrailingCholesky::supernodal_flops << " flops of factorization): " << kernels << ", " << params_.threads
            << (params_.threads == 1 ? " thread" : " threads");
    return msg.str();
}

bool Stepper::sparse_contact() const { return cache_[0] && cache_[0]->held; }

TrailingCholesky& Stepper::last_factor() {
    if (!cache_[0]) throw std::logic_error("Stepper::last_factor: no factor before the first substep");
    return cache_[0]->held ? cache_[0]->held->factor() : *cache_[0]->cholesky;
}

ContactFactorization Stepper::contact_factorization() const {
    const Factor* f = nullptr;
    for (const auto& c : cache_)
        if (c && c->id == current_factor_) f = c.get();
    if (!f || !f->held) return {};
    const Eigen::Index nc = num_contact_nodes();
    const std::vector<double>& slip = f->held->slip();
    ContactFactorization out{f->dt, std::vector<signed char>(static_cast<size_t>(nc)), {}};
    for (Eigen::Index i = 0; i < nc; ++i) {
        bool slipping = false;
        for (size_t s = static_cast<size_t>(i); s < slip.size(); s += static_cast<size_t>(nc))
            slipping = slipping || slip[s] != 0;
        out.pattern[static_cast<size_t>(i)] =
            static_cast<signed char>(!f->held->held()[static_cast<size_t>(i)]       ? 0
                                     : f->held->held()[static_cast<size_t>(nc + i)] ? 1
                                     : slipping                                     ? 3
                                                                                    : 2);
    }
    if (f->held->holds_slips()) out.slip = slip;
    return out;
}

void Stepper::set_contact_factorization(const ContactFactorization& saved) {
    current_factor_ = 0;  // none: the next factor used starts at the state's held set
    if (saved.pattern.empty()) return;
    for (const auto& c : cache_) {
        if (!c || !c->held || c->dt != saved.substep) continue;
        const Eigen::Index nc = num_contact_nodes();
        std::vector<char> held(static_cast<size_t>(c->held->unknowns()));
        for (Eigen::Index i = 0; i < nc; ++i) {
            const signed char x = saved.pattern[static_cast<size_t>(i)];
            held[static_cast<size_t>(i)] = x != 0;
            for (size_t j = static_cast<size_t>(nc + i); j < held.size(); j += static_cast<size_t>(nc))
                held[j] = x == 1;  // the tangential dofs of a sticking node
        }
        if (!saved.slip.empty() && saved.slip.size() != c->held->slip().size())
            throw std::invalid_argument("contact factorization: its slips do not fit the body");
        c->held->hold(held, saved.slip);
        current_factor_ = c->id;
    }
}

long Stepper::sparse_refactorizations() const {
    long count = 0;
    for (const auto& f : cache_)
        if (f && f->held) count += f->held->refactorizations();
    return count;
}

double Stepper::sparse_refactored_work() const {
    double work = 0;
    for (const auto& f : cache_)
        if (f && f->held) work += f->held->refactored_work();
    return work;
}

bool Stepper::wants_sparse() const {
    if (contact_path_ != ContactPath::automatic) return contact_path_ != ContactPath::condensed;
    return !rate_law(params_).active() &&
           sparse_contact_pays(num_contact_nodes(), disc_.expand.cols(), params_.friction_coefficient);
}

void Stepper::set_contact_at_end_of_step(bool at_end) {
    const MassVariant v = params_.mass_matrix;
    if (v != MassVariant::standard && v != MassVariant::standard_implicit_contact)
        throw std::logic_error(
            "Stepper::set_contact_at_end_of_step: only for a consistent mass (variants 0 and 3)");
    params_.mass_matrix = at_end ? MassVariant::standard_implicit_contact : MassVariant::standard;
    disc_.contact_at_end_of_step = at_end;
}

void Stepper::set_contact_path(ContactPath path) {
    contact_path_ = path;
    for (auto& f : cache_) f.reset();
    spare_.clear();
    problem_factor_ = 0;
}

void Stepper::set_supernodal_factor(bool supernodal) {
    supernodal_factor_ = supernodal;
    set_contact_path(contact_path_);  // the factors made again
}

std::unique_ptr<Stepper::Factor> Stepper::make_factor(double dt) {
    const bool sparse = wants_sparse();
    for (auto it = spare_.begin(); it != spare_.end(); ++it) {
        if ((*it)->dt == dt && ((*it)->held != nullptr) == sparse) {
            auto f = std::move(*it);
            spare_.erase(it);
            f->id = ++factor_ids_;
            return f;
        }
    }
    auto f = std::make_unique<Factor>();
    f->dt = dt;
    const int nc = num_contact_nodes();
    std::vector<int> contact_dofs = disc_.contact_unknowns();
    const int m = static_cast<int>(contact_dofs.size());
    SparseMatrix K = (4.0 / (dt * dt)) * disc_.M_free + disc_.A_free;
    f->K_free_clamped = (4.0 / (dt * dt)) * disc_.M_free_clamped + disc_.A_free_clamped;
    if (params_.damped()) {  // undamped, K is computed exactly as without the term
        K += (2.0 / dt) * disc_.C_free;
        f->K_free_clamped += (2.0 / dt) * disc_.C_free_clamped;
    }
    ++factorizations_;
    f->id = ++factor_ids_;
    if (sparse) {  // y and x; a 3D body's z with friction (without, its x is not used)
        const int per_node = held_unknowns_per_node(params_.friction_coefficient);
        contact_dofs.resize(static_cast<size_t>(per_node * nc));
        f->held = std::make_unique<HeldOperator>(K, contact_dofs, per_node,
                                                 FactorOptions{params_.baseline_kernels, params_.threads, supernodal_factor_});
        f->held->set_slip_coefficient(slip_coefficient());
        return f;
    }
    f->cholesky = std::make_unique<TrailingCholesky>(K, contact_dofs);

    // B rows: N_i = -e_y(i), T_i = +e_x(i).
    const Eigen::Index first = f->cholesky->size() - m;
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(m, m);
    for (int c = 0; c < m; ++c)
        S(f->cholesky->position(contact_dofs[static_cast<size_t>(c)]) - first, c) = c < nc ? -1 : 1;
    f->G = f->cholesky->trailing_block().triangularView<Eigen::Lower>().solve(S);
    f->delassus.noalias() = f->G.transpose() * f->G;
    return f;
}

void Stepper::setup_contact_problem(const Factor& f) {
    if (f.held) {  // no W: its diagonal's lower bound 1 / K_jj
        problem_.set_conditions(num_contact_nodes(), params_.friction_coefficient);
        snapshot_.delassus_diagonal.resize(f.held->unknowns());
        for (Eigen::Index j = 0; j < f.held->unknowns(); ++j)
            snapshot_.delassus_diagonal[j] = 1 / f.held->stiffness(j);
    } else {
        problem_.set_operator(f.delassus, params_.friction_coefficient);
        snapshot_.delassus_diagonal = f.delassus.diagonal();
    }
    problem_factor_ = f.id;
}

SubstepReport Stepper::substep(State& s, double dt, const SubstepLoad& load) {
    Laps laps(timing_);
    const Factor& f = factor_for(dt);
    struct Current {  // current_factor_ = f.id once the substep is done (or failed)
        int& id;
        int f;
        ~Current() { id = f; }
    } current{current_factor_, f.id};
    if (problem_factor_ != f.id) setup_contact_problem(f);
    laps.lap(timings_.factor);
    const Discretization& d = disc_;
    const int nc = num_contact_nodes();
    const bool friction = problem_.has_friction();
    const double c1 = 4.0 / (dt * dt), c2 = 2.0 / dt;
    if (s.lambda.size() != problem_.a.size()) s.lambda.setZero(problem_.a.size());

    // The unknown is the increment w = u^{k+1/2} - u^k (docs/contract.md, "Precision"): with
    // u^{k+1/2} itself the right-hand side carries 4/dt^2 M u^k, and the velocity
    // 4/dt (u^{k+1/2} - u^k) - v^k loses the digits of |u| / (v dt) to the subtraction, as
    // much more the farther the body is from where it started and the smaller dt. Here
    //   K w = 2/dt M v^k - A u^k - K_fc w_c + B^T lambda
    // has no term of the size of u^k but the force A u^k (taken without translations).
    // Clamped dofs at the midpoint: u_x = 0, u_y = mean top displacement.
    const double top_half = 0.5 * (load.top_start + load.top_end);
    bool clamp_moves = false;
    for (Eigen::Index k = 0; k < clamped_half_.size(); ++k) {
        const int dof = d.clamped_dofs[static_cast<size_t>(k)];
        clamped_half_[k] = (disc_.mesh.component(dof) == Mesh::normal ? top_half : 0.0) - s.u[dof];
        clamp_moves = clamp_moves || clamped_half_[k] != 0;
    }

    d.remove_translation(s.u, relative_);
    rhs_.noalias() = c2 * (d.M_free_rows * s.v);
    rhs_.noalias() -= d.A_free_rows * relative_;
    if (clamp_moves) rhs_.noalias() -= f.K_free_clamped * clamped_half_;  // else 0
    if (d.plate_index >= 0) {  // the plate's own inertia and the force pressing it down
        rhs_[d.plate_index] += d.plate_mass * c2 * s.v[d.top_y_dof()] - load.top_force;
    }
    // Under force control the body translates along y with the plate, as fast and as far as
    // it is pulled: the solve is for w less the translation t = dt/2 v_plate on every y
    // unknown, whose K t is exact ((4/dt^2 + 2 alpha/dt) M t, A t = 0). It then rounds
    // |K| |w - t|, not |K| |w| (docs/decisions.md, "Far travel and the energy balance").
    const double shift = d.plate_index >= 0 ? 0.5 * dt * s.v[d.top_y_dof()] : 0.0;
    if (shift != 0) {
        rhs_.noalias() -= (shift * (c1 + c2 * params_.damping_mass)) * normal_mass_;
        rhs_[d.plate_index] -= c1 * d.plate_mass * shift;
    }
    laps.lap(timings_.update);
    // The contact conditions on u^{k+1/2} (or, for the implicit-contact variants, on u^{k+1},
    // an affine map of it) shifted by B u^k.
    const bool implicit = d.contact_at_end_of_step;
    const auto gap_old = [&](int i) {  // g - u_N^k
        return params_.initial_gap + d.mesh.contact_heights[i] +
               s.u[d.mesh.dof(d.mesh.contact_nodes[i], Mesh::normal)];
    };
    SubstepReport report;
    bool touching = false;
    if (f.held) {              // the sparse system (sparse_contact.hpp): w_free_ and lambda at once
        problem_.a.setZero();  // unknown here: every substep solves, and says who touched
        set_contact_conditions(problem_, params_, implicit, dt, load, s.sticking, gap_old);
        if (shift != 0) {  // the conditions on w - t: B (w - t) = B w + shift on the normal rows
            snapshot_.gap_limit = problem_.gap_limit;
            problem_.gap_limit.array() += shift;
        }
        const ContactSolveInfo info = sparse_solver_.solve(*f.held, problem_, options_, rhs_, s.sticking,
                                                           s.lambda, w_free_, f.id != current_factor_);
        if (shift != 0) problem_.gap_limit.swap(snapshot_.gap_limit);
        touching = sparse_solver_.touching();
        report.contact_iterations = info.iterations;
        report.contact_solved = touching;
        laps.lap(timings_.contact);
    } else {
        Eigen::Map<Eigen::VectorXd> y = f.cholesky->forward(rhs_);
        laps.lap(timings_.solve);
        // Condensed contact problem on B w.
        const int unknowns = static_cast<int>(problem_.W.rows());
        const auto G = f.G.leftCols(unknowns);
        auto y_contact = y.tail(f.G.rows());
        problem_.a.noalias() = G.transpose() * y_contact;      // B K^-1 rhs
        if (shift != 0) problem_.a.head(nc).array() -= shift;  // + B t (N = -e_y)
        touching = set_contact_conditions(problem_, params_, implicit, dt, load, s.sticking, gap_old);
        if (touching) {
            const ContactSolveInfo info = solver_.solve(problem_, options_, s.lambda);
            report.contact_iterations = info.iterations;
            report.contact_sweeps = info.sweeps;
            report.contact_solved = true;
            y_contact.noalias() += G * s.lambda;  // L^-1 P B^T lambda lives in the trailing block
        } else {
            s.lambda.setZero();  // no node can touch: the contact solve is skipped
        }
        laps.lap(timings_.contact);
        f.cholesky->backward(w_free_);
        laps.lap(timings_.solve);
    }
    if (shift != 0) w_free_.noalias() += shift * normal_free_;  // w = (w - t) + t

    w_.noalias() = d.expand * w_free_;  // (the plate's w on every top y dof)
    for (size_t k = 0; k < d.clamped_dofs.size(); ++k) w_[d.clamped_dofs[k]] = clamped_half_[k];
    if (params_.damped()) {
        // C du (du = u^{k+1} - u^k) as C (du - t) + alpha M t, t du's translation (A t = 0):
        // C du itself rounds |C| |du| (docs/decisions.md, "Far travel and the energy balance").
        du_ = 2 * w_;
        d.remove_translation(du_, product_);
        C_du_.noalias() = d.C * product_;
        if (params_.damping_mass != 0) {
            product_ = du_ - product_;
            C_du_.noalias() += params_.damping_mass * (d.M * product_);
        }
        report.work.damping = du_.dot(C_du_) / dt;
    }

    // Force of the clamp (or of the plate) on the body: the top rows' residual of the midpoint
    // equation. Its work: over the clamped dofs' motion; under force control the top force's
    // over the plate's, which with the plate's kinetic energy in E closes the balance.
    for (size_t k = 0; k < d.top_dofs.size(); ++k) {
        const int dof = d.top_dofs[k];
        double r = 0;
        for (RowMajorSparseMatrix::InnerIterator it(d.M_top_rows, static_cast<Eigen::Index>(k)); it; ++it)
            r += it.value() * (c1 * w_[it.col()] - c2 * s.v[it.col()]);
        for (RowMajorSparseMatrix::InnerIterator it(d.A_top_rows, static_cast<Eigen::Index>(k)); it; ++it)
            r += it.value() * (relative_[it.col()] + w_[it.col()]);  // u^{k+1/2} - t
        if (params_.damped()) r += 0.5 * c2 * C_du_[dof];
        report.top_reaction[static_cast<size_t>(d.mesh.component(dof))] += r;
        if (d.free_index[dof] < 0) report.work.clamp += r * 2 * w_[dof];
    }
    if (d.plate_index >= 0) report.work.clamp -= load.top_force * 2 * w_free_[d.plate_index];

    // The edge: the contact law's quantities on u^{k+1/2} (for tests), then what both
    // steppers report.
    const auto node_y = [&](int i) {
        return d.mesh.dof(d.mesh.contact_nodes[static_cast<size_t>(i)], Mesh::normal);
    };
    const auto node_x = [&](int i) { return d.mesh.dof(d.mesh.contact_nodes[static_cast<size_t>(i)], 0); };
    const auto node_tangent = [&](int i, int t) {
        return d.mesh.dof(d.mesh.contact_nodes[static_cast<size_t>(i)], tangent_component(t));
    };
    snapshot_.normal_displacement.resize(nc);
    snapshot_.gap_limit = problem_.gap_limit;
    snapshot_.slip.setZero(nc);
    for (int i = 0; i < nc; ++i) {
        const double uN_old = -s.u[node_y(i)];
        snapshot_.normal_displacement[i] = uN_old - w_[node_y(i)];
        snapshot_.gap_limit[i] += uN_old;
        if (friction) snapshot_.slip[i] = w_[node_x(i)] - problem_.slip_origin[i];
    }
    record_contact(
        report, snapshot_, s.sticking, s.lambda, dt, load.foundation_velocity, d.mesh.tangents(),
        params_.initial_gap, disc_.mesh.contact_heights, touching,
        f.held ? sparse_solver_.status() : solver_.status(), [&](int i) { return -s.u[node_y(i)]; },
        [&](int i) { return -2 * w_[node_y(i)]; }, [&](int i, int t) { return 2 * w_[node_tangent(i, t)]; });

    // u^{k+1} = 2 u^{k+1/2} - u^k,  v^{k+1} = 4/dt (u^{k+1/2} - u^k) - v^k on the moving dofs;
    // the clamped dofs follow the top displacement input.
    for (int dof : d.moving_dofs) {
        s.v[dof] = 2 * c2 * w_[dof] - s.v[dof];
        s.u[dof] += 2 * w_[dof];
    }
    for (int dof : d.clamped_dofs) {
        const bool y = d.mesh.component(dof) == Mesh::normal;
        s.u[dof] = y ? load.top_end : 0.0;
        s.v[dof] = y ? load.top_rate : 0.0;
    }
    s.time += dt;
    laps.lap(timings_.update);
    return report;
}

}  // namespace contactbody
