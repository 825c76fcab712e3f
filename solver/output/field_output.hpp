// Field output as VTK XML files: one unstructured grid (.vtu) per snapshot with the
// displacement, the velocity and the nodal contact forces, and a .pvd collection that lists
// them with their times (ParaView, meshio). Data arrays are base64 binary, inline.
#pragma once

#include <string>
#include <vector>

#include "body/stepper.hpp"

namespace contactbody {

class FieldWriter {
public:
    // Creates `directory` if needed and writes an empty collection, so that an unwritable
    // directory is reported here (std::runtime_error naming the path and the cause). It owns
    // the files basename_NNNNNN.vtu there: those of an earlier run are removed.
    FieldWriter(const Mesh& mesh, std::string directory, std::string basename = "contactbody");

    // Writes snapshot number times().size() of the state at s.time, then the collection.
    void write(const State& s);
    // Forgets the snapshots from `count` on (after a rollback), their files included;
    // rewrites the collection.
    void truncate(size_t count);
    // Restores the list of written snapshots (state restore), removing the files of later ones.
    void set_times(std::vector<double> times);
    const std::vector<double>& times() const { return times_; }
    std::string file_name(size_t index) const;
    const std::string& directory() const { return directory_; }

private:
    void write_collection() const;
    void remove_snapshots_from(size_t first) const;

    const Mesh& mesh_;
    std::string directory_, basename_;
    std::vector<double> times_;
    std::string points_, cells_;  // encoded once: the mesh does not change
    std::string buffer_;
};

}  // namespace contactbody
