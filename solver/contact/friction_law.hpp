// The friction law of a scene as the contact solves take it.
#pragma once

#include "assembly/discretization.hpp"
#include "contact/contact_solver.hpp"

namespace contactbody {

// The slip-rate law of p as the contact solver takes it, with slip_time 1 (so that its slip is
// a slip rate: coefficient(F_d, v, &dF) gives F(v) and dF/dv); the stepper sets the substep's.
ContactProblem::RateLaw rate_law(const SceneParameters& p);

}  // namespace contactbody
