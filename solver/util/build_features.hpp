// What a build of the solver carries. Every build assembles 2D bodies; solid (3D) bodies, with
// their tetrahedral kernels, their isotropic friction and the supernodal LU that factors them,
// are left out of the 2D FMU's binaries (CMakeLists.txt: CONTACTBODY_SOLID_BODIES=0 where the
// platform builds make them), whose model refuses a tetrahedral mesh anyway: they would take
// ContactBody.fmu past its 5 MB limit (docs/building.md, "What the build makes").
#pragma once

#ifndef CONTACTBODY_SOLID_BODIES
#define CONTACTBODY_SOLID_BODIES 1
#endif

namespace contactbody {
inline constexpr bool solid_bodies_built = CONTACTBODY_SOLID_BODIES != 0;
}  // namespace contactbody
