// Press: an actuator mass on a damper, pushed down by a force ramp, whose position is the top
// edge of ContactBody (top_displacement); the body pushes back (top_reaction_y). Absolute
// units (N, kg), except the input top_reaction_y, ContactBody's output as it is: N per metre
// of thickness, the force of the top edge on the body, negative when it presses.
//   m x'' = -F(t) - c x' - top_reaction_y w,   F(t) = force_amplitude min(1, t / force_ramp_time)
// x is up-positive like top_displacement; position starts at initial_position.
#include "companion.hpp"

namespace companion {
namespace {

enum : unsigned {
    press_mass,
    press_damping,
    force_amplitude,
    force_ramp_time,
    contact_width,
    initial_position,
    top_reaction_y,
    position,
    velocity,
    actuator_force,
    reaction_force,
    count
};
enum { x_pos, x_vel };

double force(const double* v, double t) { return v[force_amplitude] * ramp(t, v[force_ramp_time]); }

void initial_states(const double* v, double* x) {
    x[x_pos] = v[initial_position];
    x[x_vel] = 0;
}

void derivatives(const double* v, const double* x, double t, double* dx) {
    dx[x_pos] = x[x_vel];
    dx[x_vel] =
        (-force(v, t) - v[press_damping] * x[x_vel] - v[top_reaction_y] * v[contact_width]) / v[press_mass];
}

void outputs(double* v, const double* x, double t) {
    v[position] = x[x_pos];
    v[velocity] = x[x_vel];
    v[actuator_force] = -force(v, t);
    v[reaction_force] = -v[top_reaction_y] * v[contact_width];
}

const Model the_model{
    "Press",
    "{8c41d0e2-5f3a-4b97-a6d8-1e7b2c9f4a05}",
    "Actuator mass and damper pushed by a force ramp; its position drives ContactBody's top edge",
    {
        {"press_mass", press_mass, Causality::parameter, 0.05, "kg",
         "Moving mass m of the press (with its plate)", true},
        {"press_damping", press_damping, Causality::parameter, 20, "N.s/m", "Viscous damping c of the press"},
        {"force_amplitude", force_amplitude, Causality::parameter, 150, "N",
         "Actuator force (pressing down) reached at force_ramp_time"},
        {"force_ramp_time", force_ramp_time, Causality::parameter, 5e-3, "s",
         "Time of the linear force ramp from 0 (0: a step)"},
        {"contact_width", contact_width, Causality::parameter, 0.01, "m",
         "Thickness of the body (out of plane): top_reaction_y [N/m] x width = force [N]", true},
        {"initial_position", initial_position, Causality::parameter, 0, "m", "Position at t0 (up positive)"},
        {"top_reaction_y", top_reaction_y, Causality::input, 0, "N/m",
         "ContactBody's top_reaction_y (per metre of thickness; the step's average): force of the top edge "
         "on the body, negative when pressing"},
        {"position", position, Causality::output, 0, "m",
         "Press position at the end of the step (up positive): feeds ContactBody's top_displacement"},
        {"velocity", velocity, Causality::output, 0, "m/s", "Press velocity"},
        {"actuator_force", actuator_force, Causality::output, 0, "N",
         "Actuator force on the press (negative: down)"},
        {"reaction_force", reaction_force, Causality::output, 0, "N",
         "Force of the body on the press, -top_reaction_y x contact_width (positive: up)"},
    },
    2,
    1e-6,
    initial_states,
    derivatives,
    outputs};

}  // namespace

const Model& model() { return the_model; }

}  // namespace companion
