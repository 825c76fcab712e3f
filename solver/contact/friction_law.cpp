#include "contact/friction_law.hpp"

namespace contactbody {

ContactProblem::RateLaw rate_law(const SceneParameters& p) {
    ContactProblem::RateLaw law;
    if (p.stribeck_velocity > 0) law.excess = (p.static_friction_ratio - 1) * p.friction_coefficient;
    law.stribeck_velocity = p.stribeck_velocity;
    law.viscous = p.viscous_friction;
    law.slip_time = 1;
    // The massless reduced edge has no tangential inertia either, whatever the variant.
    law.tangential_inertia = p.mass_matrix != MassVariant::redistributed_both &&
                             (p.modes == 0 || reduced_edge_has_tangential_mass(p));
    return law;
}

}  // namespace contactbody
