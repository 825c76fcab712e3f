// The FMU state (fmi2GetFMUstate) as plain data, and its versioned byte format
// (fmi2SerializeFMUstate): a header with magic, format version, payload size and checksum,
// then the payload. Nothing in it is a pointer.
#pragma once

#include <vector>

#include "model.hpp"

namespace contactbody::fmu {

struct FmuState {
    unsigned instance_state = 0;  // one bit of fmu::FmiState
    double last_successful_time = 0;
    ModelState model;
};

constexpr unsigned state_format_version = 19;  // 2: String variables, field output; 3: damping,
                                               // works; 4: cached substep sizes; 5: ramp start; 6: top force;
                                               // 7: sticking nodes; 8: edge history;
                                               // 9: the edge arrays, edge_nodes; 10: the slip-rate law;
// 11: E(0), for the blow-up guard; 12: modes (the reduced body's coordinates);
// 13: the reduced body's contact factorization;
// 14: z outputs and input (ContactBody3D's own magic); 15: baseline_kernels (ContactBody3D);
// 16: threads (ContactBody3D); 17: the contact factorization's held slips (3D slip directions);
// 18: tolerance and the controller's substep; 19: the controller's declined savings

std::vector<char> serialize(const FmuState& state);
// Throws ModelError naming the defect: wrong magic or version, truncation, checksum, sizes
// that do not match the mesh, non-finite numbers, trailing bytes.
FmuState deserialize(const char* bytes, size_t size);

}  // namespace contactbody::fmu
