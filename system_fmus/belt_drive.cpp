// BeltDrive: a motor drives the belt's pulley through a compliant shaft; the belt is the
// foundation under ContactBody. Per FMU, absolute units (N, N m, J), except the input
// friction_force, which is ContactBody's output as it is: N per metre of thickness.
//   J_m w_m' = tau(t) - k (phi_m - phi_p) - c (w_m - w_p)
//   J_p w_p' = k (phi_m - phi_p) + c (w_m - w_p) - r T w        (T = friction_force, w = width)
// tau(t) = motor_torque + torque_amplitude min(1, t / torque_ramp_time)
//          + speed_gain (speed_setpoint min(1, t / torque_ramp_time) - w_m):
// a proportional speed controller (speed_gain 0, the default, leaves the torque source alone;
// a large one makes the motor a velocity source, the classic stick-slip drive). The body's friction
// force T is the belt's force on the body (+x drags it along), so the body pulls the belt
// back with T w. load_work = int T w v dt is the work the belt does on the body; with v fed
// to foundation_velocity it matches ContactBody's foundation_work x width up to the coupling.
#include "companion.hpp"

namespace companion {
namespace {

enum : unsigned {
    motor_inertia,
    pulley_inertia,
    shaft_stiffness,
    shaft_damping,
    pulley_radius,
    contact_width,
    torque_amplitude,
    torque_ramp_time,
    motor_torque,
    friction_force,
    belt_velocity,
    motor_speed,
    shaft_torque,
    load_force,
    load_work,
    drive_work,
    speed_setpoint,
    speed_gain,  // appended: the references above stay as they were
    count
};
enum { phi_m, w_m, phi_p, w_p, x_load_work, x_drive_work };

double torque(const double* v, const double* x, double t) {
    const double r = ramp(t, v[torque_ramp_time]);
    return v[motor_torque] + v[torque_amplitude] * r + v[speed_gain] * (v[speed_setpoint] * r - x[w_m]);
}

double shaft(const double* v, const double* x) {  // N m, from the motor to the pulley
    return v[shaft_stiffness] * (x[phi_m] - x[phi_p]) + v[shaft_damping] * (x[w_m] - x[w_p]);
}

// N: the body pulls the belt back with it
double load(const double* v) { return v[friction_force] * v[contact_width]; }

void initial_states(const double*, double* x) {
    for (int i = 0; i < 6; ++i) x[i] = 0;
}

void derivatives(const double* v, const double* x, double t, double* dx) {
    const double torque_in_shaft = shaft(v, x);
    dx[phi_m] = x[w_m];
    dx[w_m] = (torque(v, x, t) - torque_in_shaft) / v[motor_inertia];
    dx[phi_p] = x[w_p];
    dx[w_p] = (torque_in_shaft - v[pulley_radius] * load(v)) / v[pulley_inertia];
    dx[x_load_work] = load(v) * (v[pulley_radius] * x[w_p]);  // force x belt velocity
    dx[x_drive_work] = torque(v, x, t) * x[w_m];
}

void outputs(double* v, const double* x, double t) {
    v[belt_velocity] = v[pulley_radius] * x[w_p];
    v[motor_speed] = x[w_m];
    v[shaft_torque] = shaft(v, x);
    v[load_force] = load(v);
    v[load_work] = x[x_load_work];
    v[drive_work] = x[x_drive_work];
    (void)t;
}

const Model the_model{
    "BeltDrive",
    "{3b9e2f4c-7a1d-4c55-8e0b-2d6f9a1c7e31}",
    "Motor, compliant shaft and belt pulley; the belt is ContactBody's foundation",
    {
        {"motor_inertia", motor_inertia, Causality::parameter, 2e-4, "kg.m2", "Motor rotor inertia J_m",
         true},
        {"pulley_inertia", pulley_inertia, Causality::parameter, 1e-4, "kg.m2",
         "Pulley and belt inertia J_p (at the pulley)", true},
        {"shaft_stiffness", shaft_stiffness, Causality::parameter, 200, "N.m/rad",
         "Torsional stiffness k of the shaft", true},
        {"shaft_damping", shaft_damping, Causality::parameter, 0.02, "N.m.s/rad",
         "Torsional damping c of the shaft"},
        {"pulley_radius", pulley_radius, Causality::parameter, 0.05, "m",
         "Pulley radius r: belt velocity = r w_p", true},
        {"contact_width", contact_width, Causality::parameter, 0.01, "m",
         "Thickness of the body (out of plane): friction_force [N/m] x width = force on the belt [N]", true},
        {"torque_amplitude", torque_amplitude, Causality::parameter, 3.0, "N.m",
         "Motor torque reached at torque_ramp_time (added to the input motor_torque)"},
        {"torque_ramp_time", torque_ramp_time, Causality::parameter, 5e-3, "s",
         "Time of the linear torque ramp from 0 (0: a step)"},
        {"motor_torque", motor_torque, Causality::input, 0, "N.m",
         "Extra motor torque (input), added to the ramp"},
        {"friction_force", friction_force, Causality::input, 0, "N/m",
         "ContactBody's friction_force (per metre of thickness; the step's average): the body pulls the belt "
         "back with friction_force x contact_width"},
        {"belt_velocity", belt_velocity, Causality::output, 0, "m/s",
         "Belt velocity r w_p at the end of the step: feeds ContactBody's foundation_velocity"},
        {"motor_speed", motor_speed, Causality::output, 0, "rad/s", "Motor speed w_m"},
        {"shaft_torque", shaft_torque, Causality::output, 0, "N.m", "Torque in the shaft"},
        {"load_force", load_force, Causality::output, 0, "N",
         "Force of the body on the belt, friction_force x contact_width (opposing +x motion)"},
        {"load_work", load_work, Causality::output, 0, "J",
         "Work of the belt on the body since t0: int friction_force contact_width belt_velocity dt"},
        {"drive_work", drive_work, Causality::output, 0, "J", "Work of the motor torque since t0"},
        {"speed_setpoint", speed_setpoint, Causality::parameter, 0, "rad/s",
         "Motor speed the controller holds (reached at torque_ramp_time, ramped like the torque); used with "
         "speed_gain > 0"},
        {"speed_gain", speed_gain, Causality::parameter, 0, "N.m.s/rad",
         "Proportional speed control: adds speed_gain (setpoint - motor_speed) to the motor torque; 0 = none "
         "(a pure torque source)"},
    },
    6,
    1e-6,
    initial_states,
    derivatives,
    outputs};

}  // namespace

const Model& model() { return the_model; }

}  // namespace companion
