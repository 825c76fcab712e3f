#include "edge_output.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace contactbody {

namespace {

constexpr size_t header_size = 320;  // a multiple of 64, as NPY asks  // fixed: the row count changes, the header's size does not

void check(bool ok, const std::string& path, const char* what) {
    if (!ok) throw std::runtime_error(std::string(what) + " " + path + " failed: " + std::strerror(errno));
}

template <class T>
void append(std::string& out, const T* data, size_t count) {
    out.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

}  // namespace

EdgeWriter::EdgeWriter(std::string path, Eigen::Index nodes)
    : path_(std::move(path)), nodes_(nodes) {
    file_ = open_file(path_, "w+b");
    check(file_ != nullptr, path_, "creating the edge history");
    write_header();
}

// NPY format 1.0: magic, version, header length, then a Python dict literal padded with
// spaces to header_size bytes in all, ending in a newline.
void EdgeWriter::write_header() {
    const std::string n = std::to_string(nodes_);
    std::string dict = "{'descr': [('time', '<f8'), ('x', '<f8', (" + n + ",)), ('pressure', '<f8', (" +
                       n + ",)), ('friction', '<f8', (" + n + ",)), ('slip_velocity', '<f8', (" + n +
                       ",)), ('gap', '<f8', (" + n + ",)), ('state', 'i1', (" + n +
                       ",))], 'fortran_order': False, 'shape': (" + std::to_string(rows_) + ",), }";
    const size_t prefix = 10;  // magic (6), version (2), header length (2)
    if (prefix + dict.size() + 1 > header_size)
        throw std::runtime_error("edge history: too many contact nodes for the header");
    dict.append(header_size - prefix - dict.size() - 1, ' ');
    dict += '\n';
    std::string header("\x93NUMPY\x01\x00", 8);
    const uint16_t length = static_cast<uint16_t>(dict.size());
    header.append(reinterpret_cast<const char*>(&length), 2);
    header += dict;
    std::FILE* f = file_.get();
    check(seek_file(f, 0) && std::fwrite(header.data(), 1, header.size(), f) == header.size() &&
              std::fflush(f) == 0,
          path_, "writing the edge history");
}

void EdgeWriter::write(double time, const EdgeSnapshot& e) {
    record_.clear();
    append(record_, &time, 1);
    for (const Eigen::VectorXd* v : {&e.x, &e.pressure, &e.friction, &e.slip_velocity, &e.gap})
        append(record_, v->data(), static_cast<size_t>(nodes_));
    append(record_, e.state.data(), static_cast<size_t>(nodes_));
    check(seek_file(file_.get(), header_size + rows_ * record_.size()) &&
              std::fwrite(record_.data(), 1, record_.size(), file_.get()) == record_.size(),
          path_, "writing the edge history");
    ++rows_;
    write_header();
}

void EdgeWriter::truncate(uint64_t rows) {
    if (rows >= rows_) return;
    rows_ = rows;
    const size_t record = 8 + static_cast<size_t>(nodes_) * (5 * 8 + 1);
    check(resize_file(file_.get(), header_size + rows_ * record), path_, "truncating the edge history");
    write_header();
}

}  // namespace contactbody
