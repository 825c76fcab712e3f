#include "output/edge_output.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace contactbody {

namespace {

// A multiple of 64, as NPY asks, and fixed: the row count changes, the header's size does not.
// A 3D body's records name three more fields.
size_t header_size_for(int tangents) { return tangents > 1 ? 448 : 320; }
// The column name's suffix of tangent t (friction, friction_z).
const char* tangent_suffix(int t) { return t == 0 ? "" : "_z"; }

void check(bool ok, const std::string& path, const char* what) {
    if (!ok) throw std::runtime_error(std::string(what) + " " + path + " failed: " + std::strerror(errno));
}

template <class T>
void append(std::string& out, const T* data, size_t count) {
    out.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

}  // namespace

EdgeWriter::EdgeWriter(std::string path, Eigen::Index nodes, int tangents)
    : path_(std::move(path)), nodes_(nodes), tangents_(tangents), header_size_(header_size_for(tangents)) {
    file_ = open_file(path_, "w+b");
    check(file_ != nullptr, path_, "creating the edge history");
    write_header();
}

// NPY format 1.0: magic, version, header length, then a Python dict literal padded with
// spaces to header_size bytes in all, ending in a newline.
void EdgeWriter::write_header() {
    const std::string n = std::to_string(nodes_);
    std::string dict = "{'descr': [('time', '<f8')";
    for (const std::string& field : fields()) dict += ", ('" + field + "', '<f8', (" + n + ",))";
    dict += ", ('state', 'i1', (" + n + ",))], 'fortran_order': False, 'shape': (" + std::to_string(rows_) +
            ",), }";
    const size_t prefix = 10;  // magic (6), version (2), header length (2)
    if (prefix + dict.size() + 1 > header_size_)
        throw std::runtime_error("edge history: too many contact nodes for the header");
    dict.append(header_size_ - prefix - dict.size() - 1, ' ');
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

std::vector<std::string> EdgeWriter::fields() const {
    std::vector<std::string> names{"x"};
    if (tangents_ > 1) names.emplace_back("z");
    names.emplace_back("pressure");
    for (const char* name : {"friction", "slip_velocity"})
        for (int t = 0; t < tangents_; ++t) names.push_back(name + std::string(tangent_suffix(t)));
    names.emplace_back("gap");
    return names;
}

void EdgeWriter::write(double time, const EdgeSnapshot& e) {
    record_.clear();
    append(record_, &time, 1);
    const auto add = [&](const Eigen::VectorXd& v) {
        append(record_, v.data(), static_cast<size_t>(nodes_));
    };
    // In fields()' order.
    add(e.x);
    if (tangents_ > 1) add(e.z);
    add(e.pressure);
    for (const auto* per_tangent : {&e.friction, &e.slip_velocity})
        for (int t = 0; t < tangents_; ++t) add((*per_tangent)[static_cast<size_t>(t)]);
    add(e.gap);
    append(record_, e.state.data(), static_cast<size_t>(nodes_));
    check(seek_file(file_.get(), header_size_ + rows_ * record_.size()) &&
              std::fwrite(record_.data(), 1, record_.size(), file_.get()) == record_.size(),
          path_, "writing the edge history");
    ++rows_;
    write_header();
}

void EdgeWriter::truncate(uint64_t rows) {
    if (rows >= rows_) return;
    rows_ = rows;
    const size_t record = 8 + static_cast<size_t>(nodes_) * (fields().size() * 8 + 1);
    check(resize_file(file_.get(), header_size_ + rows_ * record), path_, "truncating the edge history");
    write_header();
}

}  // namespace contactbody
