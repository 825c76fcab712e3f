#include "output/field_output.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "util/c_file.hpp"

namespace contactbody {

namespace {

// VTK's inline binary: base64 of (UInt64 byte count, raw little-endian data), one stream.
// (No base64 in the standard library, Eigen or CHOLMOD; the encoder is a dozen lines.)
void append_base64(std::string& out, const std::vector<unsigned char>& bytes) {
    static const char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
        for (int s : {18, 12, 6, 0}) out += table[(v >> s) & 63];
    }
    if (i < bytes.size()) {
        const bool two = i + 1 < bytes.size();
        const uint32_t v = (bytes[i] << 16) | (two ? bytes[i + 1] << 8 : 0);
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += two ? table[(v >> 6) & 63] : '=';
        out += '=';
    }
}

template <class T>
std::string encode(const std::vector<T>& values) {
    const uint64_t size = values.size() * sizeof(T);
    std::vector<unsigned char> bytes(sizeof(size) + size);
    std::memcpy(bytes.data(), &size, sizeof(size));
    if (size) std::memcpy(bytes.data() + sizeof(size), values.data(), size);
    std::string out;
    append_base64(out, bytes);
    return out;
}

std::string data_array(const char* type, const char* name, int components, const std::string& data) {
    return std::string("        <DataArray type=\"") + type + "\" Name=\"" + name +
           "\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"binary\">" + data +
           "</DataArray>\n";
}

// Writes through a temporary and a rename, so that readers never see half a file.
void write_file(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp";
    {
        File f = open_file(tmp, "wb");
        if (!f) throw std::runtime_error("cannot write " + tmp + ": " + std::strerror(errno));
        const bool written = std::fwrite(text.data(), 1, text.size(), f.get()) == text.size();
        if (std::fclose(f.release()) != 0 || !written)
            throw std::runtime_error("writing " + tmp + " failed: " + std::strerror(errno));
    }
    if (!replace_file(tmp, path))
        throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

}  // namespace

FieldWriter::FieldWriter(const Mesh& mesh, std::string directory, std::string basename)
    : mesh_(mesh), directory_(std::move(directory)), basename_(std::move(basename)) {
    if (!create_directories(directory_))
        throw std::runtime_error("result_directory '" + directory_ +
                                 "' cannot be created: " + std::strerror(errno));
    write_collection();        // fails here, at initialization, if the directory is not writable
    remove_snapshots_from(0);  // a longer earlier run's snapshots would outlive the collection

    std::vector<double> points;
    points.reserve(3 * static_cast<size_t>(mesh.num_nodes()));
    for (int n = 0; n < mesh.num_nodes(); ++n) {
        const Point p = mesh.point(n);
        points.insert(points.end(), {p.x, p.y, p.z});
    }
    std::vector<int64_t> connectivity, offsets;
    for (size_t e = 0; e < mesh.num_cells(); ++e) {
        connectivity.insert(connectivity.end(), mesh.cell(e), mesh.cell(e) + mesh.nodes_per_cell());
        offsets.push_back(static_cast<int64_t>(connectivity.size()));
    }
    const std::vector<uint8_t> types(mesh.num_cells(), mesh.dim == 2 ? 5 : 10);  // VTK_TRIANGLE, VTK_TETRA
    points_ = data_array("Float64", "Points", 3, encode(points));
    cells_ = data_array("Int64", "connectivity", 1, encode(connectivity)) +
             data_array("Int64", "offsets", 1, encode(offsets)) +
             data_array("UInt8", "types", 1, encode(types));
}

std::string FieldWriter::file_name(size_t index) const {
    char number[32];
    std::snprintf(number, sizeof number, "_%06zu.vtu", index);
    return basename_ + number;
}

void FieldWriter::write(const State& s) {
    const size_t nodes = static_cast<size_t>(mesh_.num_nodes());
    std::vector<double> u(3 * nodes, 0.0), v(3 * nodes, 0.0), force(3 * nodes, 0.0), pressure(nodes, 0.0);
    for (size_t n = 0; n < nodes; ++n) {
        for (int c = 0; c < mesh_.dim; ++c) {
            u[3 * n + c] = s.u[mesh_.dof(static_cast<int>(n), c)];
            v[3 * n + c] = s.v[mesh_.dof(static_cast<int>(n), c)];
        }
    }
    // Multipliers of the last substep: the force on the body is (lambda_T, -lambda_N).
    const Eigen::Index nc = static_cast<Eigen::Index>(mesh_.contact_nodes.size());
    const bool friction = s.lambda.size() > nc;
    if (s.lambda.size() >= nc) {
        for (Eigen::Index i = 0; i < nc; ++i) {
            const size_t n = static_cast<size_t>(mesh_.contact_nodes[static_cast<size_t>(i)]);
            const double share = mesh_.edge_share(static_cast<size_t>(i));
            force[3 * n] = friction ? s.lambda[nc + i] : 0.0;
            if (friction && s.lambda.size() == 3 * nc) force[3 * n + 2] = s.lambda[2 * nc + i];
            force[3 * n + 1] = -s.lambda[i];
            pressure[n] = -s.lambda[i] / share;
        }
    }
    buffer_.clear();
    buffer_ +=
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n"
        "  <!-- contact_force (N per metre of thickness, on the body) and contact_pressure "
        "(Pa) are those of the last substep, instantaneous: the scalar outputs normal_force "
        "and friction_force are averages over the communication step -->\n"
        "  <UnstructuredGrid>\n";
    buffer_ += "    <Piece NumberOfPoints=\"" + std::to_string(nodes) + "\" NumberOfCells=\"" +
               std::to_string(mesh_.num_cells()) + "\">\n";
    buffer_ += "      <PointData Vectors=\"displacement\">\n";
    buffer_ += data_array("Float64", "displacement", 3, encode(u));
    buffer_ += data_array("Float64", "velocity", 3, encode(v));
    buffer_ += data_array("Float64", "contact_force", 3, encode(force));
    buffer_ += data_array("Float64", "contact_pressure", 1, encode(pressure));
    buffer_ += "      </PointData>\n      <Points>\n" + points_ + "      </Points>\n";
    buffer_ += "      <Cells>\n" + cells_ + "      </Cells>\n";
    buffer_ += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    write_file(join_path(directory_, file_name(times_.size())), buffer_);
    times_.push_back(s.time);
    write_collection();
}

void FieldWriter::truncate(size_t count) {
    if (count < times_.size()) times_.resize(count);
    write_collection();
    remove_snapshots_from(times_.size());
}

// Removes this writer's snapshot files (basename_NNNNNN.vtu) numbered `first` and up: the
// directory then holds exactly the files its collection lists.
void FieldWriter::remove_snapshots_from(size_t first) const {
    for (const std::string& name : directory_entries(directory_)) {
        const size_t digits = name.size() - basename_.size() - 5;  // "_" ... ".vtu"
        if (name.size() != basename_.size() + 11 || name.compare(0, basename_.size(), basename_) != 0 ||
            name[basename_.size()] != '_' || name.compare(name.size() - 4, 4, ".vtu") != 0)
            continue;
        const std::string number = name.substr(basename_.size() + 1, digits);
        if (number.find_first_not_of("0123456789") != std::string::npos) continue;
        if (std::stoul(number) >= first) remove_file(join_path(directory_, name));
    }
}

void FieldWriter::set_times(std::vector<double> times) {
    times_ = std::move(times);
    write_collection();
    remove_snapshots_from(times_.size());
}

void FieldWriter::write_collection() const {
    std::string text =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
        "byte_order=\"LittleEndian\">\n  <Collection>\n";
    char time[40];
    for (size_t k = 0; k < times_.size(); ++k) {
        std::snprintf(time, sizeof time, "%.17g", times_[k]);
        text += std::string("    <DataSet timestep=\"") + time + "\" part=\"0\" file=\"" + file_name(k) +
                "\"/>\n";
    }
    text += "  </Collection>\n</VTKFile>\n";
    write_file(join_path(directory_, basename_ + ".pvd"), text);
}

}  // namespace contactbody
