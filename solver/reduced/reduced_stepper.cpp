#include "reduced/reduced_stepper.hpp"

#include "reduced/clamp_rows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "util/text.hpp"

namespace contactbody {

namespace {
// The body with its top clamped (the basis' discretization under force control).
Discretization clamped_discretization(const SceneParameters& p) {
    SceneParameters clamped = p;
    clamped.force_control = false;
    return discretize(clamped);
}
}  // namespace

ReducedStepper::ReducedStepper(const SceneParameters& params, int modes)
    : params_(params),
      disc_(discretize(params)),
      clamped_(params.force_control ? std::optional<Discretization>(clamped_discretization(params))
                                    : std::nullopt),
      basis_(build_modal_basis(basis_disc(), modes, reduced_edge_has_tangential_mass(params))),
      plate_mass_(params.force_control ? params.top_mass : 0.0) {
    check_reduced_edge(params);
    const Discretization& d = basis_disc();
    const Eigen::Index m = basis_.modes.cols(), k = basis_.residual.cols();
    nd_ = m + k;
    nx_ = basis_.constraint.cols();
    const Eigen::Index n = nd_ + nx_;
    nf_ = static_cast<Eigen::Index>(d.free_dofs.size());
    omega2_.resize(n);
    omega2_ << basis_.omega2, Eigen::VectorXd::Ones(k), Eigen::VectorXd::Zero(nx_);
    mass_.resize(n);
    mass_ << Eigen::VectorXd::Ones(m), Eigen::VectorXd::Zero(k), Eigen::VectorXd::Zero(nx_);
    const Eigen::MatrixXd& TC = basis_.constraint;  // the X coordinates' columns of T
    if (nx_ > 0) {
        const Eigen::MatrixXd MTC = d.M_free * TC, ATC = d.A_free * TC;
        mass_mx_ = basis_.modes.transpose() * MTC;
        const Eigen::MatrixXd Mxx = TC.transpose() * MTC, Axx = TC.transpose() * ATC;
        mass_xx_ = 0.5 * (Mxx + Mxx.transpose());
        stiffness_xx_ = 0.5 * (Axx + Axx.transpose());
        stiffness_xx_factor_.compute(stiffness_xx_);
    }

    const int nc = num_contact_nodes();
    tangents_ = d.mesh.tangents();
    const Eigen::Index rows = (1 + tangents_) * nc;
    Bhat_.resize(rows, n);
    Blift_.resize(rows);
    // N_i = -e_y(i), T_i = +e_x(i) (and a 3D body's +e_z(i)), as the stepper's B.
    const std::vector<int> tangential = tangential_contact_dofs(d);
    for (Eigen::Index r = 0; r < rows; ++r) {
        const bool normal = r < nc;
        const int dof =
            normal ? d.contact_y[static_cast<size_t>(r)] : tangential[static_cast<size_t>(r - nc)];
        const double sign = normal ? -1.0 : 1.0;
        Bhat_.row(r).head(nd_) << sign * basis_.modes.row(dof), sign * basis_.residual.row(dof);
        Bhat_.row(r).tail(nx_) = sign * TC.row(dof);
        Blift_[r] = sign * basis_.lift[dof];
    }
    tangential_rows_are_x_ = nx_ > 0 && Bhat_.bottomRows(rows - nc).leftCols(nd_).isZero(0) &&
                             Bhat_.bottomRows(rows - nc).rightCols(nx_).isIdentity(0);

    // The clamp: e = 1 on the clamped y dofs.
    const Eigen::Index ncl = static_cast<Eigen::Index>(d.clamped_dofs.size());
    Eigen::VectorXd e = Eigen::VectorXd::Zero(ncl);
    for (Eigen::Index j = 0; j < ncl; ++j)
        e[j] = d.mesh.component(d.clamped_dofs[static_cast<size_t>(j)]) == Mesh::normal;
    Eigen::VectorXd all_e = Eigen::VectorXd::Zero(d.mesh.num_dofs());
    for (Eigen::Index j = 0; j < ncl; ++j) all_e[d.clamped_dofs[static_cast<size_t>(j)]] = e[j];
    const Eigen::VectorXd& S = basis_.lift;
    const Eigen::VectorXd MS = d.M_free * S, Me = d.M_free_clamped * e, AS = d.A_free * S;
    m_s_ = Eigen::VectorXd::Zero(n);
    m_c_ = Eigen::VectorXd::Zero(n);
    m_s_.head(m) = basis_.modes.transpose() * MS;
    m_c_.head(m) = basis_.modes.transpose() * Me;
    m_s_.tail(nx_) = TC.transpose() * MS;
    m_c_.tail(nx_) = TC.transpose() * Me;
    a_s_.resize(n);
    a_s_ << basis_.modes.transpose() * AS, basis_.residual.transpose() * AS, TC.transpose() * AS;
    m_t_ = m_s_ + m_c_;
    mu_ss_ = S.dot(MS);
    mu_cs_ = S.dot(Me);
    mu_cc_ = all_e.dot(d.M * all_e);
    mass_tt_ = mu_ss_ + 2 * mu_cs_ + mu_cc_;
    s_ss_ = S.dot(AS);

    // The clamped x (and a 3D body's z) dofs' rows against the basis, the lift and the clamp
    // (residual massless).
    const auto clamp_rows = [&](int component) {
        const ClampXRows rows = clamp_x_rows(d, component);
        const Eigen::VectorXd &M_fx = rows.mass_free, &A_fx = rows.stiffness_free;
        ClampRows c;
        c.mass = Eigen::VectorXd::Zero(n);
        c.mass.head(m) = basis_.modes.transpose() * M_fx;
        c.mass.tail(nx_) = TC.transpose() * M_fx;
        c.stiffness.resize(n);
        c.stiffness << basis_.modes.transpose() * A_fx, basis_.residual.transpose() * A_fx,
            TC.transpose() * A_fx;
        c.mass_lift = S.dot(M_fx);
        c.stiffness_lift = S.dot(A_fx);
        c.mass_top = rows.mass_top;
        c.stiffness_top = rows.stiffness_top;
        return c;
    };
    for (int t = 0; t < d.mesh.tangents(); ++t)
        clamp_tangential_[static_cast<size_t>(t)] = clamp_rows(tangent_component(t));

    start_run();
    problem_.tangents = tangents_;
    problem_.a.resize(rows);
    problem_.gap_limit.resize(nc);
    problem_.slip_origin.resize(tangents_ * nc);
    rhs_.resize(n);
    w_.resize(n);
    contact_u_.resize(rows);
    normal_u_.resize(nc);
    normal_u_at_.setConstant(n + 1, std::numeric_limits<double>::quiet_NaN());  // matches no state
    bw_.resize(rows);
    du_.resize(n);
    contact_force_.resize(n);
    dw_.resize(n);
    tail_.resize(nx_);
    form_.resize(nx_);
}

// What a new stepper of params_ is, but for the discretization, the basis and the operators.
void ReducedStepper::start_run() {
    damping_ = params_.damping_mass * mass_ + params_.damping_stiffness * omega2_;
    if (nx_ > 0) damping_xx_ = params_.damping_mass * mass_xx_ + params_.damping_stiffness * stiffness_xx_;
    options_ = ContactSolverOptions{};
    options_.tolerance = params_.contact_tolerance;
    // Its substep's cost is the contact solve's (benchmarks/results/contact_profile.md).
    options_.update_factorization = true;
    options_.project_slip = true;
    solver_ = ContactSolver{};
    snapshot_ = ContactSnapshot{};
    problem_dt_ = -1;
    saved_factorization_ = {};
}

void ReducedStepper::restart(const SceneParameters& params) {
    if (!same_discretization(params_, params))
        throw std::logic_error("ReducedStepper::restart: the parameters define another discretization");
    check_parameters(params);
    params_ = params;
    start_run();
    ++restarts_;
}

std::string ReducedStepper::summary() const {
    Text msg;
    msg << "reduced body: " << basis_.modes.cols() << " modes (of " << finite_mode_count(basis_disc())
        << " finite) and " << basis_.residual.cols() << " residual attachment modes of the "
        << num_contact_nodes() << " contact nodes"
        << (nx_ > 0 ? " (normal), the tangential-mass edge: its x dofs kept with their constraint modes"
                    : ", the massless edge")
        << "; basis " << (restarts_ > 0 ? "kept from the last run (built" : "built") << " in "
        << basis_.setup_seconds << " s, " << (basis_.dense ? "dense eigensolver" : "Lanczos, ")
        << (basis_.dense ? "" : std::to_string(basis_.operator_applications) + " operator applications")
        << (restarts_ > 0 ? ")" : "");
    return msg.str();
}

State ReducedStepper::from_full(const State& full) const {
    const Discretization& d = basis_disc();
    const Eigen::Index n = size();
    State s;
    Eigen::VectorXd u, v;                                             // the free dofs' motion less the lift's
    split_off_lift(d, d.top_y_dof(), basis_.lift, full, n, s, u, v);  // the clamp's (or the plate's) value
    const auto project = [&](const Eigen::VectorXd& x, auto&& z) {    // A_hat^-1 T^T A x
        const Eigen::VectorXd Ax = d.A_free * x;
        z.head(nd_) << basis_.modes.transpose() * Ax, basis_.residual.transpose() * Ax;
        z.head(nd_) = z.head(nd_).cwiseQuotient(omega2_.head(nd_));
        if (nx_ > 0) z.tail(nx_) = stiffness_xx_factor_.solve(basis_.constraint.transpose() * Ax);
    };
    project(u, s.u.head(n));
    project(v, s.v.head(n));
    return s;
}

void ReducedStepper::to_full(const State& s, State& full) const {
    const Discretization& d = basis_disc();
    const Eigen::Index m = basis_.modes.cols(), n = size();
    const Eigen::VectorXd u = basis_.modes * s.u.head(m) + basis_.residual * s.u.segment(m, nd_ - m) +
                              basis_.constraint * s.u.segment(nd_, nx_) + basis_.lift * s.u[n];
    const Eigen::VectorXd v = basis_.modes * s.v.head(m) + basis_.residual * s.v.segment(m, nd_ - m) +
                              basis_.constraint * s.v.segment(nd_, nx_) + basis_.lift * s.v[n];
    expand_to_full(d, u, v, s, n, full);
}

State ReducedStepper::initial_state(double top_displacement) const {
    return from_full(Stepper::paper_initial_state(disc_, params_, top_displacement));
}

std::pair<double, double> ReducedStepper::kinetic_and_strain_energy(const State& s) {
    const Eigen::Index n = size();
    const auto z = s.u.head(n), zdot = s.v.head(n);
    const double tau = s.v[n], tc = s.v[n + 1], top = s.u[n + 1], gap = s.u[n] - top;
    double tail_kinetic = 0, tail_strain = 0;  // the X block's terms
    if (nx_ > 0) {
        const TailProducts& t = tail_products(z, zdot);
        const auto zdot_x = zdot.tail(nx_);
        tail_kinetic = 2 * zdot_x.dot(t.mass_modes) + zdot_x.dot(t.mass_x);
        tail_strain = z.tail(nx_).dot(t.stiffness);
    }
    const double kinetic =
        0.5 * (zdot.cwiseAbs2().dot(mass_) + tail_kinetic) + zdot.dot(m_s_ * tau + m_c_ * tc) +
        0.5 * (mu_ss_ * tau * tau + 2 * mu_cs_ * tau * tc + mu_cc_ * tc * tc) + 0.5 * plate_mass_ * tc * tc;
    // With A_fc e = -A_ff S: 1/2 z^T A_hat z + z^T a_s (lift - top) + 1/2 S^T A_ff S (lift - top)^2
    // (the lift and clamp moving together, a translation, store none).
    const double strain =
        0.5 * (z.cwiseAbs2().dot(omega2_) + tail_strain) + z.dot(a_s_) * gap + 0.5 * s_ss_ * gap * gap;
    // Both are positive semi-definite forms, here expanded into terms that cancel for a body
    // moving rigidly: what is left below zero is round-off (an outside check reported
    // E = -2.7e-13 J/m; not reproduced here), and
    // the full body's energies are >= 0 by construction.
    return {std::max(kinetic, 0.0), std::max(strain, 0.0)};
}

const ReducedStepper::TailProducts& ReducedStepper::tail_products(
    const Eigen::Ref<const Eigen::VectorXd>& z, const Eigen::Ref<const Eigen::VectorXd>& zdot) const {
    TailProducts& t = tail_products_;
    if (t.zdot.size() != zdot.size() || t.zdot != zdot || t.z_x != z.tail(nx_)) {
        t.zdot = zdot;
        t.z_x = z.tail(nx_);
        t.mass_modes.noalias() = mass_mx_.transpose() * zdot.head(modes());
        t.mass_x.noalias() = mass_xx_ * zdot.tail(nx_);
        t.stiffness.noalias() = stiffness_xx_ * z.tail(nx_);
    }
    return t;
}

double ReducedStepper::tail_damping_form(const Eigen::Ref<const Eigen::VectorXd>& x) const {
    if (nx_ == 0) return 0;
    form_.noalias() = damping_xx_ * x.tail(nx_);
    if (params_.damping_mass != 0)
        form_.noalias() += (2 * params_.damping_mass) * mass_mx_.transpose() * x.head(modes());
    return x.tail(nx_).dot(form_);
}

void ReducedStepper::solve_step(const StepOperators& ops, Eigen::Ref<Eigen::VectorXd> x) const {
    if (nx_ == 0) {
        x = x.cwiseProduct(ops.inverse_stiffness);
        return;
    }
    // Eliminate the diagonal block, solve the Schur complement on X, substitute back.
    Eigen::VectorXd& t = tail_;
    t = x.tail(nx_);
    t.noalias() -= ops.tail_coupling.transpose() * x.head(modes());
    x.tail(nx_).noalias() = ops.tail_schur_inverse * t;
    x.head(nd_) = x.head(nd_).cwiseProduct(ops.inverse_stiffness.head(nd_));
    x.head(modes()).noalias() -= ops.tail_coupling * x.tail(nx_);
}

double ReducedStepper::energy(const ReducedState& s) const {
    const auto [kinetic, strain] = const_cast<ReducedStepper*>(this)->kinetic_and_strain_energy(s);
    return kinetic + strain;
}

double ReducedStepper::contact_height(const State& s, int node) const {
    return -(Bhat_.row(node).dot(s.u.head(size())) + Blift_[node] * s.u[size()]);
}

// The residual's block of B_hat is lower trapezoidal (build_modal_basis rotates it so): the
// products read its lower part only, about half of B_hat at nx = 160 with 80 modes.
void ReducedStepper::edge_product(Eigen::Index r0, Eigen::Index rows,
                                  const Eigen::Ref<const Eigen::VectorXd>& x,
                                  Eigen::Ref<Eigen::VectorXd> y) const {
    const Eigen::Index nc = num_contact_nodes();
    if (!tangential_rows_are_x_ || r0 + rows <= nc) return stored_rows_product(r0, rows, x, y);
    const Eigen::Index normal = std::max<Eigen::Index>(0, nc - r0);
    if (normal > 0) stored_rows_product(r0, normal, x, y.head(normal));
    y.tail(rows - normal) = x.tail(nx_).segment(r0 + normal - nc, rows - normal);
}

void ReducedStepper::stored_rows_product(Eigen::Index r0, Eigen::Index rows,
                                         const Eigen::Ref<const Eigen::VectorXd>& x,
                                         Eigen::Ref<Eigen::VectorXd> y) const {
    const Eigen::Index m = modes(), k = nd_ - m, dense = std::min(r0, k);
    y.noalias() = Bhat_.block(r0, 0, rows, m) * x.head(m);
    if (dense > 0) y.noalias() += Bhat_.block(r0, m, rows, dense) * x.segment(m, dense);
    if (r0 < k)
        y.noalias() +=
            Bhat_.block(r0, m + r0, rows, k - r0).triangularView<Eigen::Lower>() * x.segment(m + r0, k - r0);
    if (nx_ > 0) y.noalias() += Bhat_.block(r0, nd_, rows, nx_) * x.tail(nx_);
}

void ReducedStepper::edge_transposed_product(Eigen::Index rows,
                                             const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                             Eigen::Ref<Eigen::VectorXd> y) const {
    const Eigen::Index nc = num_contact_nodes();
    if (tangential_rows_are_x_ && rows > nc) {  // the tangential rows add lambda_T on X
        edge_transposed_product(nc, lambda.head(nc), y);
        y.tail(nx_) += lambda.segment(nc, rows - nc);
        return;
    }
    const Eigen::Index m = modes(), k = nd_ - m;
    y.head(m).noalias() = Bhat_.topLeftCorner(rows, m).transpose() * lambda;
    y.segment(m, k).noalias() =
        Bhat_.block(0, m, rows, k).triangularView<Eigen::Lower>().transpose() * lambda;
    if (nx_ > 0) y.tail(nx_).noalias() = Bhat_.block(0, nd_, rows, nx_).transpose() * lambda;
}

const Eigen::VectorXd& ReducedStepper::normal_displacements(const State& s) const {
    const auto at = s.u.head(size() + 1);  // z and the lift's coordinate
    if (normal_u_at_.size() != at.size() || normal_u_at_ != at) {
        const Eigen::Index nc = num_contact_nodes();
        edge_product(0, nc, at.head(size()), normal_u_);
        normal_u_ += Blift_.head(nc) * at[size()];
        normal_u_at_ = at;
    }
    return normal_u_;
}

void ReducedStepper::contact_heights(const State& s, Eigen::Ref<Eigen::VectorXd> out) const {
    out = -normal_displacements(s);
}

bool ReducedStepper::set_clamp(State& s, double top, double rate) const {
    const Eigen::Index n = size();
    const bool moves = s.u[n + 1] != top || s.v[n + 1] != rate;
    s.u[n + 1] = top;
    s.v[n + 1] = rate;
    return moves;
}

bool ReducedStepper::fits(const State& s) const {
    const Eigen::Index nc = num_contact_nodes();
    return s.u.size() == size() + 2 && s.v.size() == size() + 2 &&
           (s.lambda.size() == nc || s.lambda.size() == (1 + tangents_) * nc) && s.sticking.size() == nc;
}

ContactFactorization ReducedStepper::contact_factorization() const {
    if (problem_dt_ <= 0) return saved_factorization_;  // not yet used since it was set
    return {problem_dt_, solver_.factored_pattern(problem_.revision), {}};
}

std::vector<double> ReducedStepper::cached_substeps() const {
    std::vector<double> sizes;
    for (const auto& ops : cache_)
        if (ops) sizes.push_back(ops->dt);
    return sizes;
}

void ReducedStepper::set_cached_substeps(const std::vector<double>& sizes) {
    if (sizes.size() > cache_.size())
        throw std::invalid_argument("more cached substep sizes than the cache holds");
    for (auto& ops : cache_) ops.reset();
    for (size_t k = sizes.size(); k-- > 0;) build_operators(sizes[k]);  // the first ends first
    problem_dt_ = -1;
}

void ReducedStepper::set_friction_coefficient(double friction) {
    if (friction != params_.friction_coefficient) saved_factorization_ = {};  // W's with the other
    params_.friction_coefficient = friction;
    problem_dt_ = -1;
}

const ReducedStepper::StepOperators& ReducedStepper::operators_for(double dt) {
    for (size_t j = 0; j < cache_.size(); ++j)
        if (cache_[j] && std::abs(cache_[j]->dt - dt) <= 1e-14 * dt) return *cache_[j];
    return build_operators(dt);
}

ReducedStepper::StepOperators& ReducedStepper::build_operators(double dt) {
    std::swap(cache_[0], cache_[1]);
    auto ops = std::make_unique<StepOperators>();
    ops->dt = dt;
    const double c1 = 4.0 / (dt * dt), c2 = 2.0 / dt;
    const double c = c1 + c2 * params_.damping_mass;
    ops->inverse_stiffness = (c1 * mass_ + c2 * damping_ + omega2_).cwiseInverse();
    if (nx_ == 0) {
        ops->delassus = Bhat_ * ops->inverse_stiffness.asDiagonal() * Bhat_.transpose();
    } else {
        ops->inverse_stiffness.tail(nx_).setZero();
        ops->tail_coupling = c * (ops->inverse_stiffness.head(modes()).asDiagonal() * mass_mx_);
        Eigen::MatrixXd schur = c * mass_xx_ + (1 + c2 * params_.damping_stiffness) * stiffness_xx_ -
                                c * mass_mx_.transpose() * ops->tail_coupling;
        const Eigen::LLT<Eigen::MatrixXd> factor(0.5 * (schur + schur.transpose()));
        if (factor.info() != Eigen::Success)
            throw std::runtime_error("the tangential-mass edge's step matrix is not positive definite");
        ops->tail_schur_inverse = factor.solve(Eigen::MatrixXd::Identity(nx_, nx_));
        ops->tail_schur_inverse =
            0.5 * (ops->tail_schur_inverse + ops->tail_schur_inverse.transpose()).eval();
        Eigen::MatrixXd response = Bhat_.transpose();  // K^-1 B_hat^T
        for (Eigen::Index j = 0; j < response.cols(); ++j) solve_step(*ops, response.col(j));
        ops->delassus = Bhat_ * response;
        ops->delassus = 0.5 * (ops->delassus + ops->delassus.transpose()).eval();
    }
    if (params_.force_control) {
        // The plate's row: the lift's mass with the plate's (C has the body's mass only), and
        // no stiffness (A S = 0). W gains the rank-one g g^T / schur, g = B S - c B T h.
        const double k_pp = c1 * (mass_tt_ + plate_mass_) + c2 * params_.damping_mass * mass_tt_;
        ops->plate_coupling = m_t_;
        solve_step(*ops, ops->plate_coupling);
        ops->plate_schur = k_pp - c * c * m_t_.dot(ops->plate_coupling);
        const Eigen::VectorXd g = Blift_ - c * (Bhat_ * ops->plate_coupling);
        ops->delassus += g * g.transpose() / ops->plate_schur;
    }
    cache_[0] = std::move(ops);
    ++operator_builds_;
    return *cache_[0];
}

SubstepReport ReducedStepper::substep(ReducedState& s, double dt, const SubstepLoad& load) {
    const StepOperators& ops = operators_for(dt);
    const int nc = num_contact_nodes();
    const bool friction = params_.friction_coefficient > 0;
    if (problem_dt_ != dt || problem_friction_ != friction) {
        problem_.set_operator(ops.delassus, params_.friction_coefficient);
        problem_dt_ = dt;
        problem_friction_ = friction;
        if (saved_factorization_.substep == dt) solver_.factor_at(saved_factorization_.pattern);
        saved_factorization_ = {};
    }
    const double c1 = 4.0 / (dt * dt), c2 = 2.0 / dt;
    const double alpha = params_.damping_mass, beta = params_.damping_stiffness;
    if (s.lambda.size() != problem_.W.rows()) s.lambda.setZero(problem_.W.rows());

    // The state's parts (State's layout for the reduced body: reduced_stepper.hpp).
    const Eigen::Index n = size();
    auto z = s.u.head(n), zdot = s.v.head(n);
    double& lift_at = s.u[n];
    double& lift_rate = s.v[n];
    double& top = s.u[n + 1];
    double& top_rate = s.v[n + 1];

    // The midpoint equation on z with the clamp's midpoint increment w_t (no stiffness
    // coupling: the lift is the clamp's static response):
    //   K_hat w = 2/dt (M_hat zdot + m_t top_rate) - A_hat z - (4/dt^2 + 2/dt alpha) m_t w_t + B_hat^T lambda.
    // Under force control w_t is the plate's, an unknown: its row
    //   c m_t^T w + k_pp w_t = 2/dt (m_t^T zdot + (m_lift + m_p) v_p) - top_force + (B S)^T lambda
    // is eliminated through the Schur complement (build_operators).
    const double c = c1 + c2 * alpha;
    const bool plate = params_.force_control;
    double w_t = plate ? 0.0 : 0.5 * (load.top_start + load.top_end) - top;
    rhs_ = c2 * (mass_.cwiseProduct(zdot) + m_s_ * lift_rate + m_c_ * top_rate) - omega2_.cwiseProduct(z) -
           a_s_ * (lift_at - top) - c * w_t * m_t_;
    if (nx_ > 0) {  // M_hat's and A_hat's X block
        const TailProducts& t = tail_products(z, zdot);
        rhs_.head(modes()).noalias() += c2 * mass_mx_ * zdot.tail(nx_);
        rhs_.tail(nx_) += c2 * (t.mass_modes + t.mass_x) - t.stiffness;
    }
    w_ = rhs_;
    solve_step(ops, w_);
    if (plate) {
        w_t = (c2 * (m_t_.dot(zdot) + (mass_tt_ + plate_mass_) * top_rate) - load.top_force -
               c * m_t_.dot(w_)) /
              ops.plate_schur;
        w_ -= c * w_t * ops.plate_coupling;
    }
    // B_hat is the substep's largest operand with W (about 1 MB each at nx = 160), and its
    // products are bound by the memory they read: only the rows used are formed. The normal
    // rows of B u^k (-u_y of the contact nodes: the gaps), and B w.
    contact_u_.head(nc) = normal_displacements(s);
    edge_product(0, bw_.size(), w_, bw_);
    bw_ += Blift_ * w_t;

    problem_.a = bw_.head(problem_.a.size());
    const bool touching = set_contact_conditions(
        problem_, params_, disc_.contact_at_end_of_step, dt, load, s.sticking,
        [&](int i) { return params_.initial_gap + disc_.mesh.contact_heights[i] - contact_u_[i]; });
    SubstepReport report;
    const Eigen::Index unknowns = problem_.W.rows();
    if (touching) {
        const ContactSolveInfo info = solver_.solve(problem_, options_, s.lambda);
        report.contact_iterations = info.iterations;
        report.contact_sweeps = info.sweeps;
        report.contact_solved = true;
        edge_transposed_product(unknowns, s.lambda, contact_force_);
        dw_ = contact_force_;
        solve_step(ops, dw_);
        w_ += dw_;
        if (plate) {  // the plate's share of the contact forces' response
            const double dw_t =
                (Blift_.head(unknowns).dot(s.lambda) - c * ops.plate_coupling.dot(contact_force_)) /
                ops.plate_schur;
            w_ -= c * dw_t * ops.plate_coupling;
            w_t += dw_t;
        }
        // B (w + dw) = a + W lambda (W = B K^-1 B^T with the plate's row): the solver's
        // last product, at its solution. Without friction its tangential rows are formed.
        bw_.head(unknowns) = solver_.displacements();
        if (!friction) {
            const Eigen::Index t = tangents_ * nc;
            edge_product(nc, t, w_, bw_.tail(t));
            bw_.tail(t) += Blift_.tail(t) * w_t;
        }
    } else {
        s.lambda.setZero();
    }

    // Damping work dt vbar^T C vbar, vbar = 2 w / dt on every dof: C = alpha M + beta A,
    // whose A part does not couple z with the lift and clamp (A_fc e = -A_ff S).
    const double du_t = 2 * w_t;
    du_ = 2 * w_;
    if (params_.damped())
        report.work.damping = (du_.cwiseAbs2().dot(damping_) + tail_damping_form(du_) +
                               2 * du_t * alpha * m_t_.dot(du_) + alpha * mass_tt_ * du_t * du_t) /
                              dt;

    // The clamp's force on the body: the clamp moves the lift with it, so its force is the
    // residual of the reduced equations' rows of both (lift and clamp), less the contact
    // forces' share through the lift, (B S)^T lambda. Its work closes the reduced body's own
    // energy balance; with every finite mode the lift's row is zero and this is the clamped
    // rows' residual, as in the full body.
    double r = m_t_.dot(c1 * w_ - c2 * zdot) + (mu_ss_ + mu_cs_) * (c1 * w_t - c2 * lift_rate) +
               (mu_cs_ + mu_cc_) * (c1 * w_t - c2 * top_rate);
    if (params_.damped()) r += 0.5 * c2 * alpha * (m_t_.dot(du_) + mass_tt_ * du_t);
    r -= Blift_.head(unknowns).dot(s.lambda);
    report.top_reaction[Mesh::normal] = r;
    // The clamp's work, or the top force's over the plate's motion (the plate's kinetic energy
    // is in E).
    report.work.clamp = plate ? -load.top_force * du_t : r * du_t;
    // The clamped tangential rows' residual, recovered from the basis as the full body's.
    const ClampRows::Substep clamp_substep{c1,  c2,       w_t,   lift_at, lift_rate,
                                           top, top_rate, alpha, beta,    params_.damped()};
    for (int t = 0; t < tangents_; ++t)
        report.top_reaction[static_cast<size_t>(tangent_component(t))] =
            clamp_tangential_[static_cast<size_t>(t)].residual(clamp_substep, z, zdot, w_, du_);

    record_contact(
        report, snapshot_, s.sticking, s.lambda, dt, load.foundation_velocity, static_cast<int>(tangents_),
        params_.initial_gap, disc_.mesh.contact_heights, touching, solver_.status(),
        [&](int i) { return contact_u_[i]; }, [&](int i) { return 2 * bw_[i]; },
        [&](int i, int t) { return 2 * bw_[(1 + t) * nc + i]; });

    zdot = 2 * c2 * w_ - zdot;
    z += 2 * w_;
    lift_rate = 2 * c2 * w_t - lift_rate;
    lift_at += du_t;
    top = plate ? lift_at : load.top_end;
    top_rate = plate ? lift_rate : load.top_rate;
    s.time += dt;
    return report;
}

}  // namespace contactbody
