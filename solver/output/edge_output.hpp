// The bottom edge over time in one NumPy file (.npy, a structured array, one record per
// output time): time, and per contact node x, pressure, friction (Pa, step averages),
// slip_velocity (m/s), gap (m) and state (0 open, 1 stick, 2 slip); a 3D body's records add
// z and the second tangent's friction and slip velocity. np.load reads it; the
// header's row count is rewritten with every record, so the file is valid at all times.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "simulation/simulation.hpp"
#include "util/c_file.hpp"

namespace contactbody {

class EdgeWriter {
public:
    // Creates (or empties) the file; throws std::runtime_error naming the path and the cause.
    // tangents: the body's (the friction and slip velocity columns per node: x, and in 3D z).
    EdgeWriter(std::string path, Eigen::Index nodes, int tangents = 1);
    void write(double time, const EdgeSnapshot& edge);
    // Keeps the first `rows` records (after a rollback).
    void truncate(uint64_t rows);
    uint64_t rows() const { return rows_; }
    const std::string& path() const { return path_; }

private:
    void write_header();
    // The Float64 fields of a record, in the file's order (the state follows them).
    std::vector<std::string> fields() const;
    std::string path_;
    Eigen::Index nodes_;
    int tangents_;
    size_t header_size_;
    uint64_t rows_ = 0;
    File file_;
    std::string record_;  // one record's bytes, reused
};

}  // namespace contactbody
