// What the project has measured about where the scheme is unstable, as advice at
// initialization (docs/contract.md, "Warnings"): the maps are generated from
// examples/results (cmake/stability_map.py), so the FMU warns exactly where they say.
#pragma once

#include <string>

#include "assembly/discretization.hpp"

namespace contactbody {

// One message naming the settings to change, or "" where the measured maps see no growth:
// - with friction: steady sliding is unstable below the smallest stabilizing damping_stiffness
//   of the damped stability map (examples/damped_stability.py, about the admissible steady
//   state; the larger of the measured rows around F on the nearest measured mesh), and does
//   not exist from the smallest F at which the map found no steady state (the body wedges);
// - without friction, variants 0-2: the frictionless map's max E / E(0) over 20 ms above
//   frictionless_growth_limit (examples/frictionless_stability.py).
// The maps are measured on the paper's square body (lambda/mu = 2 for the damped one); other
// bodies are placed on them by the dimensionless numbers that decide the scheme: cells across
// the height, lambda/mu, the Courant number c_p dt / h, and beta in units of H / c_p.
// - with a slip-rate law: F and dF/dv at the sliding speed placed on the rate map
//   (examples/rate_stability.py: F x dF/dv x beta), where it covers them; where it does not,
//   the message says so and judges the damped map at F(sliding speed), which ignores dF/dv.
std::string scheme_warning(const SceneParameters& p, double sliding_speed = 0);

// The reduced body with the massless edge, where its substeps can have several solutions at
// any size (no tangential mass: as redistributed_both, paper section 6): friction that drops
// with the slip rate, or F > c/b. Names the setting that keeps the tangential mass; empty
// where none of this applies.
std::string massless_edge_warning(const SceneParameters& p);

// The reduced body on a long contact edge: its edge's operators are dense in the contact
// unknowns, and the full body's sparse contact solve is as fast where (contact unknowns)^2
// reaches reduced_edge_ratio times the full body's unknowns, and faster beyond
// (docs/meshes.md, "A refined contact boundary"). Names modes = 0; empty for the full body or
// a shorter edge.
constexpr double reduced_edge_ratio = 100;
std::string long_reduced_edge_warning(const SceneParameters& p, long contact_unknowns, long unknowns);

// The smallest friction coefficient from which the damped stability map found no steady
// sliding state (the clamped body wedges) on the mesh nearest this body's; inf where none.
double wedging_friction(const SceneParameters& p);

// "Gains energy": more than 10 % in 20 ms without friction and with the top held.
constexpr double frictionless_growth_limit = 1.1;

}  // namespace contactbody
