// Quantities with a value per tangent of the foundation's plane (x, then a 3D body's z) or per
// component (x, y, z). One type for both bodies: a 2D body's z entry stays 0 (or empty), so that
// no code below the variable table branches on the dimension or names a z twin.
#pragma once

#include <array>

namespace contactbody {

constexpr int max_tangents = 2;
// The displacement component of tangent t: x, then z (the normal is y, Mesh::normal).
constexpr int tangent_component(int t) { return t == 0 ? 0 : 2; }
// The letter that names component c in a message ("initial_velocity_" + it).
constexpr char component_letter(int c) { return "xyz"[c]; }

template <class T>
using PerTangent = std::array<T, max_tangents>;
using Tangential = PerTangent<double>;
using PerComponent = std::array<double, 3>;

}  // namespace contactbody
