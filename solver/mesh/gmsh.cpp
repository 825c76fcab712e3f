#include "mesh/gmsh.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "util/c_file.hpp"
#include "util/text.hpp"

namespace contactbody {

namespace {

// A token as a message quotes it: bytes outside printable ASCII (a NUL would end the message
// where a C string carries it, a byte-order mark is invisible) as \xNN.
std::string shown(std::string_view t) {
    static const char hex[] = "0123456789ABCDEF";
    std::string out;
    for (unsigned char c : t.substr(0, 80)) {
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    if (t.size() > 80) out += "...";
    return out;
}

// Whitespace-separated tokens of the whole file, each knowing its line; a quoted token
// ("contact") is one token without its quotes.
class Tokens {
public:
    Tokens(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {}

    [[noreturn]] void fail(const std::string& what, int line = -1) const {
        Text msg;
        msg << "mesh " << path_ << ", line " << (line < 0 ? line_ : line) << ": " << what;
        throw std::invalid_argument(msg.str());
    }
    bool at_end() {
        skip_blanks();
        return pos_ >= text_.size();
    }
    int line() const { return line_; }
    std::string_view next(const char* what) {
        if (at_end()) fail(std::string("the file ends where ") + what + " should be");
        if (text_[pos_] == '"') {
            const size_t close = text_.find('"', pos_ + 1);
            if (close == std::string::npos) fail("a quoted name has no closing quote");
            std::string_view t(text_.data() + pos_ + 1, close - pos_ - 1);
            pos_ = close + 1;
            return t;
        }
        const size_t start = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        return std::string_view(text_.data() + start, pos_ - start);
    }
    long integer(const char* what) {
        const std::string_view t = next(what);
        section_end(t, what);
        long value = 0;
        const auto [stop, error] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (error != std::errc() || stop != t.data() + t.size())
            fail(std::string(what) + " must be a whole number (got \"" + shown(t) + "\")");
        return value;
    }
    // A node's tag, positive as Gmsh writes them (refused at its own line).
    long node_tag() {
        const long tag = integer("a node tag");
        if (tag <= 0) fail("node tag " + std::to_string(tag) + ": Gmsh's node tags are positive");
        return tag;
    }
    long count(const char* what, long limit) {
        const long n = integer(what);
        if (n < 0 || n > limit) {
            Text msg;
            msg << what << " must be between 0 and " << limit << " (got " << n << ")";
            fail(msg.str());
        }
        return n;
    }
    // A coordinate: any number the format can write, nan and inf included (checked later,
    // with the node's tag).
    double real(const char* what) {
        const std::string_view token = next(what);
        // from_chars takes no '+': one is skipped, if a digit or a point follows (not "+-1").
        std::string_view t = token;
        if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
        section_end(token, what);
        double value = 0;
        const auto [stop, error] = std::from_chars(t.data(), t.data() + t.size(), value);
        if ((error != std::errc() && error != std::errc::result_out_of_range) || stop != t.data() + t.size())
            fail(std::string(what) + " must be a number (got \"" + shown(token) + "\")");
        return value;
    }
    void expect(std::string_view word) {
        const int at = (skip_blanks(), line_);
        const std::string_view t = next(std::string(word).c_str());
        if (t != word) fail("expected " + std::string(word) + ", found \"" + shown(t) + "\"", at);
    }
    // Past "$End<name>" (a section this reader does not need).
    void skip_section(std::string_view name) {
        const std::string end = "$End" + std::string(name.substr(1));
        while (next(end.c_str()) != end) {
        }
    }

private:
    // A section's end where a number should be: a block holds fewer entries than its header says.
    void section_end(std::string_view t, const char* what) const {
        if (t.size() > 4 && t.substr(0, 4) == "$End")
            fail("the section ends (\"" + shown(t) + "\") where " + what +
                 " should be: a block or "
                 "the section holds fewer entries than its header declares (a damaged file)");
    }
    void skip_blanks() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
            if (text_[pos_] == '\n') ++line_;
            ++pos_;
        }
    }
    std::string path_, text_;
    size_t pos_ = 0;
    int line_ = 1;
};

// Bytes a file may hold per node the body may have: a node's line and its share of the
// triangles' and boundary lines' (about 150 bytes as Gmsh writes them), with room to spare.
constexpr uint64_t max_bytes_per_node = 256;

// The whole file, which must be a regular one (a FIFO or a device would block or never end)
// of at most `max_bytes`; every failure names the file, at line 0 (the file as a whole).
// `nul`, where given, stops the reading at the first NUL byte (an ASCII MSH file holds none, a
// damaged or binary one may end in gigabytes of them) and says where it was.
std::string read_whole_file(const std::string& path, uint64_t max_bytes, size_t* nul = nullptr) {
    const auto fail = [&](const std::string& what) {
        Text msg;
        msg << "mesh " << path << ", line 0: " << what;
        throw std::invalid_argument(msg.str());
    };
    uint64_t size = 0;
    const PathKind kind = path_kind(path, size);
    if (kind == PathKind::missing) fail(std::string("cannot open it (") + std::strerror(errno) + ")");
    if (kind == PathKind::directory) fail("it is a folder, not a file");
    if (kind == PathKind::other)
        fail("it is not a regular file (a device, a pipe or a socket): only files are read");
    const auto too_large = [&](uint64_t bytes) {
        Text msg;
        msg << "the file holds " << (bytes > max_bytes ? "more than " : "") << max_bytes
            << " bytes, more than a mesh of the most nodes a body may have needs";
        fail(msg.str());
    };
    if (size > max_bytes) too_large(size);
    File f = open_file(path, "rb");
    if (!f) fail(std::string("cannot open it (") + std::strerror(errno) + ")");
    std::string text;
    try {
        text.reserve(static_cast<size_t>(size));
        char buffer[1 << 16];
        size_t n;
        while ((n = std::fread(buffer, 1, sizeof buffer, f.get())) > 0) {
            if (text.size() + n > max_bytes) too_large(text.size() + n);  // it grew
            if (const char* at = nul ? static_cast<const char*>(std::memchr(buffer, 0, n)) : nullptr) {
                text.append(buffer, static_cast<size_t>(at - buffer));
                *nul = text.size();
                return text;
            }
            text.append(buffer, n);
        }
    } catch (const std::bad_alloc&) {
        fail("out of memory reading it (" + std::to_string(size) + " bytes)");
    }
    if (std::ferror(f.get())) fail(std::string("cannot read it (") + std::strerror(errno) + ")");
    return text;
}

// Gmsh's element types: number of nodes, and why it is refused (empty: taken).
struct ElementType {
    int nodes;
    const char* refused;
};
bool element_type(long type, ElementType& t) {
    static const std::map<long, ElementType> types = {
        {15, {1, ""}},
        {1, {2, ""}},
        {2, {3, ""}},
        {8, {3, "a 3-node (second-order) line"}},
        {26, {4, "a 4-node (third-order) line"}},
        {9, {6, "a 6-node (second-order) triangle"}},
        {20, {9, "a 9-node (third-order) triangle"}},
        {21, {10, "a 10-node (third-order) triangle"}},
        {3, {4, "a 4-node quadrangle"}},
        {10, {9, "a 9-node quadrangle"}},
        {16, {8, "an 8-node quadrangle"}},
        {4, {4, ""}},
        {5, {8, "a hexahedron (3D)"}},
        {6, {6, "a prism (3D)"}},
        {7, {5, "a pyramid (3D)"}},
        {11, {10, "a 10-node (second-order) tetrahedron (3D)"}},
        {12, {27, "a 27-node hexahedron (3D)"}},
        {13, {18, "an 18-node prism (3D)"}},
        {14, {14, "a 14-node pyramid (3D)"}},
        {17, {20, "a 20-node hexahedron (3D)"}},
        {18, {15, "a 15-node prism (3D)"}},
        {19, {13, "a 13-node pyramid (3D)"}},
    };
    const auto it = types.find(type);
    if (it == types.end()) return false;
    t = it->second;
    return true;
}

struct RawElement {
    long tag;
    int line;
    int dim;
    std::vector<long> nodes;
    std::vector<long> physicals;  // the physical groups (tags, of its dimension) it belongs to
};

struct RawNode {
    double x, y, z;
    int line;
};

uint64_t digest(const std::string& text) {
    uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    return h;
}

struct RawMesh {
    uint64_t digest = 0;
    std::map<std::pair<int, long>, std::string> physical_names;  // (dim, tag) -> name
    std::map<long, RawNode> nodes;                               // tag -> node
    std::vector<RawElement> elements;
};

constexpr long max_count = 100'000'000;

void read_physical_names(Tokens& in, RawMesh& m) {
    const long n = in.count("the number of physical names", max_count);
    for (long k = 0; k < n; ++k) {
        const int dim = static_cast<int>(in.count("a physical name's dimension", 3));
        const long tag = in.integer("a physical tag");
        m.physical_names[{dim, tag}] = std::string(in.next("a physical name"));
    }
    in.expect("$EndPhysicalNames");
}

// MSH 4.1's entities: (dim, tag) -> its physical tags.
using Entities = std::map<std::pair<int, long>, std::vector<long>>;

void read_entities(Tokens& in, Entities& entities) {
    long counts[4];
    for (long& c : counts) c = in.count("an entity count", max_count);
    for (int dim = 0; dim < 4; ++dim)
        for (long k = 0; k < counts[dim]; ++k) {
            const long tag = in.integer("an entity tag");
            for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) in.real("an entity's bounding box");
            std::vector<long>& physicals = entities[{dim, tag}];
            const long np = in.count("an entity's number of physical tags", max_count);
            for (long p = 0; p < np; ++p) physicals.push_back(in.integer("a physical tag"));
            if (dim > 0) {
                const long nb = in.count("an entity's number of bounding entities", max_count);
                for (long b = 0; b < nb; ++b) in.integer("a bounding entity's tag");
            }
        }
    in.expect("$EndEntities");
}

void add_node(Tokens& in, RawMesh& m, long tag, int line, long max_nodes) {
    RawNode node;
    node.line = line;
    node.x = in.real("a node's x");
    node.y = in.real("a node's y");
    node.z = in.real("a node's z");
    if (!m.nodes.emplace(tag, node).second)
        in.fail("node " + std::to_string(tag) + " is defined twice", line);
    if (static_cast<long>(m.nodes.size()) > max_nodes)
        in.fail("more than " + std::to_string(max_nodes) + " nodes, the most a body may have", line);
}

void check_node_count(Tokens& in, long n, long max_nodes) {
    if (n > max_nodes) in.fail(std::to_string(n) + " nodes: a body has at most " + std::to_string(max_nodes));
}

// MSH 4.1's section headers state the count and the tags' range of what the blocks hold: a
// header that contradicts its blocks is a damaged file, refused as 2.2's count is (2.2 reads
// exactly its count, and then expects the section's end).
struct Header41 {
    int line;
    long count, smallest, largest;
};
Header41 read_header_41(Tokens& in, const char* what) {
    Header41 h{};
    in.at_end();
    h.line = in.line();
    h.count = in.count((std::string("the number of ") + what + "s").c_str(), max_count);
    h.smallest = in.integer((std::string("the smallest ") + what + " tag").c_str());
    h.largest = in.integer((std::string("the largest ") + what + " tag").c_str());
    return h;
}
void check_header_41(Tokens& in, const Header41& h, const char* what, long count, long smallest,
                     long largest) {
    Text msg;
    if (count != h.count)
        msg << "the section declares " << h.count << " " << what << "s, its blocks hold " << count;
    else if (count > 0 && (smallest != h.smallest || largest != h.largest))
        msg << "the section declares " << what << " tags " << h.smallest << " to " << h.largest
            << ", its blocks hold " << smallest << " to " << largest;
    else
        return;
    in.fail(msg.str() + " (a damaged file)", h.line);
}

void read_nodes_41(Tokens& in, RawMesh& m, long max_nodes) {
    const long blocks = in.count("the number of node blocks", max_count);
    const Header41 header = read_header_41(in, "node");
    check_node_count(in, header.count, max_nodes);
    for (long b = 0; b < blocks; ++b) {
        const int dim = static_cast<int>(in.count("a node block's dimension", 3));
        in.integer("a node block's entity tag");
        const long parametric = in.count("a node block's parametric flag", 1);
        const long n = in.count("a node block's number of nodes", max_count);
        std::vector<long> tags(static_cast<size_t>(n));
        for (long& t : tags) t = in.node_tag();
        for (long t : tags) {
            in.at_end();
            const int line = in.line();
            add_node(in, m, t, line, max_nodes);
            if (parametric)
                for (int p = 0; p < dim; ++p) in.real("a node's parametric coordinate");
        }
    }
    check_header_41(in, header, "node", static_cast<long>(m.nodes.size()),
                    m.nodes.empty() ? 0 : m.nodes.begin()->first,
                    m.nodes.empty() ? 0 : m.nodes.rbegin()->first);
    in.expect("$EndNodes");
}

void read_nodes_22(Tokens& in, RawMesh& m, long max_nodes) {
    const long n = in.count("the number of nodes", max_count);
    check_node_count(in, n, max_nodes);
    for (long k = 0; k < n; ++k) {
        in.at_end();
        const int line = in.line();
        const long tag = in.node_tag();
        add_node(in, m, tag, line, max_nodes);
    }
    in.expect("$EndNodes");
}

void read_element_nodes(Tokens& in, long type, RawElement& e) {
    ElementType t{};
    if (!element_type(type, t))
        in.fail("element type " + std::to_string(type) +
                    " is not one Gmsh writes: "
                    "ContactBody needs a mesh with first-order triangles (2D) or tetrahedra (3D)",
                e.line);
    if (*t.refused)
        in.fail(std::string("element ") + std::to_string(e.tag) + " is " + t.refused +
                    ": ContactBody needs a mesh with first-order triangles (2D) or tetrahedra (3D) "
                    "(Gmsh: Mesh.ElementOrder = 1, no recombination)",
                e.line);
    e.dim = type == 15 ? 0 : type == 1 ? 1 : type == 2 ? 2 : 3;
    for (int k = 0; k < t.nodes; ++k) e.nodes.push_back(in.integer("an element's node tag"));
}

void read_elements_41(Tokens& in, RawMesh& m, const Entities& entities) {
    const long blocks = in.count("the number of element blocks", max_count);
    const Header41 header = read_header_41(in, "element");
    const size_t first = m.elements.size();
    long smallest = 0, largest = 0;
    for (long b = 0; b < blocks; ++b) {
        const int dim = static_cast<int>(in.count("an element block's dimension", 3));
        const long entity = in.integer("an element block's entity tag");
        const long type = in.integer("an element type");
        const long n = in.count("an element block's number of elements", max_count);
        const auto it = entities.find({dim, entity});
        for (long k = 0; k < n; ++k) {
            RawElement e;
            in.at_end();
            e.line = in.line();
            e.tag = in.integer("an element tag");
            read_element_nodes(in, type, e);
            if (it != entities.end()) e.physicals = it->second;
            smallest = m.elements.size() == first ? e.tag : std::min(smallest, e.tag);
            largest = m.elements.size() == first ? e.tag : std::max(largest, e.tag);
            m.elements.push_back(std::move(e));
        }
    }
    check_header_41(in, header, "element", static_cast<long>(m.elements.size() - first), smallest, largest);
    in.expect("$EndElements");
}

void read_elements_22(Tokens& in, RawMesh& m) {
    const long n = in.count("the number of elements", max_count);
    for (long k = 0; k < n; ++k) {
        RawElement e;
        in.at_end();
        e.line = in.line();
        e.tag = in.integer("an element tag");
        const long type = in.integer("an element type");
        const long ntags = in.count("an element's number of tags", 1000);
        std::vector<long> tags;
        for (long t = 0; t < ntags; ++t) tags.push_back(in.integer("an element tag's value"));
        read_element_nodes(in, type, e);
        if (ntags > 0 && tags[0] != 0) e.physicals.push_back(tags[0]);  // 2.2: physical first
        m.elements.push_back(std::move(e));
    }
    in.expect("$EndElements");
}

uint64_t max_file_bytes(long max_nodes) {
    return max_bytes_per_node * static_cast<uint64_t>(max_nodes) + (1u << 20);
}

RawMesh read_raw(const std::string& path, long max_nodes) {
    size_t nul = std::string::npos;
    std::string text = read_whole_file(path, max_file_bytes(max_nodes), &nul);
    const uint64_t file_digest = digest(text);
    const bool has_byte_order_mark = text.compare(0, 3, "\xEF\xBB\xBF") == 0;
    const int nul_line =
        nul == std::string::npos ? 0 : 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    Tokens in(path, std::move(text));
    if (nul != std::string::npos) {  // a binary file is named as such (below), else the NUL
        Tokens header = in;
        bool binary = false;
        try {
            header.expect("$MeshFormat");
            header.next("the format's version");
            binary = header.next("the format's file type") != "0";
        } catch (const std::invalid_argument&) {
        }
        if (!binary) {
            Text msg;
            msg << "byte " << nul << " is a NUL byte (\\x00), which an ASCII MSH file never holds (a "
                << "damaged file)";
            in.fail(msg.str(), nul_line);
        }
    }
    if (in.at_end()) in.fail("the file is empty (a Gmsh MSH file starts with $MeshFormat)");
    if (has_byte_order_mark)
        in.fail(
            "the file starts with a UTF-8 byte-order mark (the bytes EF BB BF, invisible in "
            "most editors) before $MeshFormat: save it without one");
    in.expect("$MeshFormat");
    const std::string version(in.next("the format's version"));
    const std::string file_type(in.next("the format's file type"));
    if (file_type != "0")
        in.fail("a binary MSH file (file type " + shown(file_type) +
                "): save it as ASCII (Gmsh: "
                "Mesh.Binary = 0, or gmsh -format msh41 without -bin)");
    if (version != "4.1" && version != "2.2")
        in.fail("MSH version " + shown(version) +
                " is not read: save it as MSH 4.1 or 2.2, ASCII "
                "(Gmsh: -format msh41 or msh22)");
    in.next("the format's data size");
    in.expect("$EndMeshFormat");
    RawMesh m;
    m.digest = file_digest;
    Entities entities;
    bool nodes = false, elements = false;
    while (!in.at_end()) {
        const int line = in.line();
        const std::string section(in.next("a section"));
        if (section.empty() || section[0] != '$')
            in.fail("expected a section ($Name), found \"" + shown(section) + "\"", line);
        if (section == "$PhysicalNames") {
            read_physical_names(in, m);
        } else if (section == "$Entities" && version == "4.1") {
            read_entities(in, entities);
        } else if (section == "$Nodes") {
            if (nodes) in.fail("a second $Nodes section", line);
            version == "4.1" ? read_nodes_41(in, m, max_nodes) : read_nodes_22(in, m, max_nodes);
            nodes = true;
        } else if (section == "$Elements") {
            if (elements) in.fail("a second $Elements section", line);
            version == "4.1" ? read_elements_41(in, m, entities) : read_elements_22(in, m);
            elements = true;
        } else {
            in.skip_section(section);
        }
    }
    if (!nodes || !elements)
        in.fail(std::string("the file has no ") + (nodes ? "$Elements" : "$Nodes") + " section", 0);
    return m;
}

std::string node_where(long tag, const RawNode& n, int dim) {
    Text msg;
    msg << "node " << tag << " (" << n.x << ", " << n.y;
    if (dim == 3) msg << ", " << n.z;
    msg << ")";
    return msg.str();
}

// What a cell and a facet of a body of this dimension are called.
struct Words {
    const char *cell, *cells, *facets, *facet_dimension, *extent;
};
Words words(int dim) {
    if (dim == 2) return {"triangle", "triangles", "lines", "lines (dimension 1)", "length"};
    return {"tetrahedron", "tetrahedra", "surfaces", "surfaces (dimension 2)", "area"};
}

}  // namespace

uint64_t gmsh_file_digest(const std::string& path, long max_nodes) {
    try {
        return digest(read_whole_file(path, max_file_bytes(max_nodes)));
    } catch (const std::invalid_argument&) {
        return 0;
    }
}

Mesh read_gmsh_mesh(const std::string& path, long max_nodes, std::vector<std::string>& notes) {
    const RawMesh raw = read_raw(path, max_nodes);
    const auto fail = [&](const std::string& what, int line) {
        Text msg;
        msg << "mesh " << path << ", line " << line << ": " << what;
        throw std::invalid_argument(msg.str());
    };
    // The body's dimension is its highest cells': tetrahedra make a 3D body, else triangles a 2D one.
    int dim = 2;
    for (const RawElement& e : raw.elements) dim = std::max(dim, e.dim);
    const Words w = words(dim);
    const auto where = [&](long tag, const RawNode& n) { return node_where(tag, n, dim); };
    for (const auto& [tag, n] : raw.nodes) {
        // A body in metres lies within 1000 km of its origin: a coordinate beyond is a damaged
        // file or another unit (and would make areas and stiffnesses overflow).
        constexpr double max_coordinate = 1e6;
        for (const auto& [name, value] : {std::pair{"x", n.x}, std::pair{"y", n.y}, std::pair{"z", n.z}}) {
            if (!std::isfinite(value))
                fail("node " + std::to_string(tag) + " has " + name + " = " + format_number(value) +
                         ": every coordinate must be a finite number",
                     n.line);
            if (std::abs(value) > max_coordinate)
                fail("node " + std::to_string(tag) + " has " + name + " = " + format_number(value) +
                         " m, beyond the 1e6 m a body in metres may reach: a damaged file, or a "
                         "mesh in other units",
                     n.line);
        }
        if (dim == 2 && n.z != 0)
            fail("node " + std::to_string(tag) + " has z = " + format_number(n.z) +
                     ", but the file "
                     "holds no tetrahedra: a 2D body (triangles) must lie in the x-y plane (z = 0), and "
                     "a 3D body needs its tetrahedra in the file (Gmsh saves only the elements of "
                     "physical groups once any is defined: give the volume a physical group)",
                 n.line);
    }
    // The groups' tags by name, per dimension.
    std::map<std::string, std::vector<std::pair<int, long>>> groups;
    for (const auto& [key, name] : raw.physical_names) groups[name].push_back(key);
    const auto in_group = [&](const RawElement& e, const char* name) {
        const auto it = groups.find(name);
        if (it == groups.end()) return false;
        for (long p : e.physicals)
            for (const auto& key : it->second)
                if (key.first == e.dim && key.second == p) return true;
        return false;
    };

    Mesh m;
    m.dim = dim;
    m.source = path;
    m.file_digest = raw.digest;
    // Points in the order of their tags (a file written from the rectangle numbers its nodes
    // as the rectangle does).
    std::unordered_map<long, int> index;  // node tag -> point
    std::vector<long> tag_of;
    for (const auto& [tag, n] : raw.nodes) {
        index.emplace(tag, static_cast<int>(m.points.size()));
        m.points.push_back({n.x, n.y, n.z});
        tag_of.push_back(tag);
    }
    std::vector<int> cell_lines;
    std::vector<long> cell_tags;
    std::vector<char> used(m.points.size(), 0);
    for (const RawElement& e : raw.elements) {
        if (e.dim != dim) continue;
        for (long tag : e.nodes) {
            const auto it = index.find(tag);
            if (it == index.end())
                fail("element " + std::to_string(e.tag) + " names node " + std::to_string(tag) +
                         ", which $Nodes does not define",
                     e.line);
            m.cells.push_back(it->second);
            used[static_cast<size_t>(it->second)] = 1;
        }
        cell_lines.push_back(e.line);
        cell_tags.push_back(e.tag);
    }
    if (m.cells.empty())
        fail(
            "the file holds no triangles: ContactBody needs a mesh with first-order triangles (2D) or "
            "tetrahedra (3D)",
            0);
    for (size_t n = 0; n < used.size(); ++n)
        if (!used[n]) {
            const RawNode& r = raw.nodes.at(tag_of[n]);
            fail(where(tag_of[n], r) + " belongs to no " + w.cell +
                     " (Gmsh writes such nodes, "
                     "for example the centres of arcs, when Mesh.SaveAll = 1: save without it, "
                     "or with the physical groups only)",
                 r.line);
        }

    // Orientation: counter-clockwise triangles, tetrahedra of positive volume, as the assembly
    // expects. A mesh whose cells all turn the other way (a surface facing -z, a volume
    // mirrored) is turned over as a whole; one that mixes the two is folded.
    const size_t cells = m.num_cells();
    std::vector<double> measures;
    size_t negative = 0;
    for (size_t t = 0; t < cells; ++t) {
        const int* c = m.cell(t);
        const Point& o = m.point(c[0]);
        double edges[3][3] = {};
        double scale = 0;
        for (int a = 1; a <= dim; ++a) {
            const Point& q = m.point(c[a]);
            const double e[3] = {q.x - o.x, q.y - o.y, q.z - o.z};
            for (int k = 0; k < 3; ++k) {
                edges[a - 1][k] = e[k];
                scale = std::max(scale, std::abs(e[k]));
            }
        }
        double measure;
        if (dim == 2) {
            measure = 0.5 * (edges[0][0] * edges[1][1] - edges[1][0] * edges[0][1]);
        } else {
            measure = (edges[0][0] * (edges[1][1] * edges[2][2] - edges[1][2] * edges[2][1]) -
                       edges[0][1] * (edges[1][0] * edges[2][2] - edges[1][2] * edges[2][0]) +
                       edges[0][2] * (edges[1][0] * edges[2][1] - edges[1][1] * edges[2][0])) /
                      6;
        }
        // (no std::pow: the FMU's binaries take no math from the host's libm)
        if (!(std::abs(measure) > 1e-10 * (dim == 2 ? scale * scale : scale * scale * scale)))
            fail(dim == 2 ? "triangle " + std::to_string(cell_tags[t]) + " is degenerate (area " +
                                format_number(measure) + " m^2: its three nodes are on one line or coincide)"
                          : "tetrahedron " + std::to_string(cell_tags[t]) + " is flat (volume " +
                                format_number(measure) + " m^3: its four nodes are on one plane or coincide)",
                 cell_lines[t]);
        measures.push_back(measure);
        if (measure < 0) ++negative;
    }
    const char* turn_negative = dim == 2 ? "clockwise" : "of negative volume (left-handed)";
    const char* turn_positive = dim == 2 ? "counter-clockwise" : "of positive volume";
    if (negative == cells) {
        for (size_t t = 0; t < cells; ++t) std::swap(m.cells[t * (dim + 1) + 1], m.cells[t * (dim + 1) + 2]);
        notes.push_back(dim == 2 ? "mesh " + path +
                                       ": every triangle was clockwise (its surface faces -z); "
                                       "all were turned counter-clockwise"
                                 : "mesh " + path +
                                       ": every tetrahedron had negative volume (a mirrored "
                                       "mesh); all were turned over");
    } else if (negative > 0) {
        const bool minority_negative = 2 * negative <= cells;
        for (size_t t = 0; t < measures.size(); ++t)
            if ((measures[t] < 0) == minority_negative)
                fail(std::string(w.cell) + " " + std::to_string(cell_tags[t]) + " is inverted: it is " +
                         (minority_negative ? turn_negative : turn_positive) + " where " +
                         std::to_string(minority_negative ? cells - negative : negative) + " others are " +
                         (minority_negative ? turn_positive : turn_negative) + " (a folded mesh)",
                     cell_lines[t]);
    }

    // The boundary groups.
    for (const char* name : {"contact", "clamp"})
        if (!groups.count(name))
            fail(std::string("no physical group named \"") + name + "\": the mesh needs one of boundary " +
                     w.facets +
                     " named \"contact\" (may touch the foundation) and one named \"clamp\" (driven "
                     "as the top edge)",
                 0);
    std::vector<char> contact(m.points.size(), 0), clamp(m.points.size(), 0);
    std::vector<int> contact_facets;
    size_t contact_elements = 0, clamp_elements = 0;
    static const char* const kinds[] = {"point", "line", "triangle", "tetrahedron"};
    static const char* const kinds_of[] = {"points (dimension 0)", "lines (dimension 1)",
                                           "surfaces (dimension 2)", "volumes (dimension 3)"};
    for (const RawElement& e : raw.elements) {
        const bool c = in_group(e, "contact"), k = in_group(e, "clamp");
        if (!c && !k) continue;
        std::vector<int> nodes;
        for (long tag : e.nodes) {
            const auto it = index.find(tag);
            if (it == index.end())
                fail("element " + std::to_string(e.tag) + " of the " + (c ? "contact" : "clamp") +
                         " group names node " + std::to_string(tag) + ", which no " + w.cell + " has",
                     e.line);
            nodes.push_back(it->second);
        }
        for (int n : nodes) {
            if (c) contact[static_cast<size_t>(n)] = 1;
            if (k) clamp[static_cast<size_t>(n)] = 1;
        }
        // Both groups are boundary facets (a contact group may add points): a clamp of edges
        // or corners would hold only those nodes, a volume group every node.
        const bool facet = e.dim == dim - 1, point = e.dim == 0;
        for (const auto& [name, wrong] :
             {std::pair{"contact", c && !facet && !point}, std::pair{"clamp", k && !facet}})
            if (wrong)
                fail("the physical group \"" + std::string(name) + "\" holds " + kinds[e.dim] + " " +
                         std::to_string(e.tag) + ": it must be a group of boundary " + w.facet_dimension +
                         ", not of " + kinds_of[e.dim],
                     e.line);
        if (c && e.dim == dim - 1) contact_facets.insert(contact_facets.end(), nodes.begin(), nodes.end());
        contact_elements += c;
        clamp_elements += k;
    }
    if (contact_elements == 0) fail("the physical group \"contact\" holds no element of this mesh", 0);
    if (clamp_elements == 0) fail("the physical group \"clamp\" holds no element of this mesh", 0);
    size_t both = 0;
    for (int n = 0; n < m.num_nodes(); ++n) {
        if (clamp[static_cast<size_t>(n)]) {
            m.top_nodes.push_back(n);
            if (contact[static_cast<size_t>(n)]) ++both;
        } else if (contact[static_cast<size_t>(n)]) {
            m.contact_nodes.push_back(n);
        }
    }
    if (both > 0)
        notes.push_back(
            "mesh " + path + ": " + std::to_string(both) + " node" + (both > 1 ? "s" : "") +
            " of both the contact and the clamp group driven by the clamp (not in the contact set)");
    if (m.contact_nodes.empty())
        fail("every node of the contact group is also the clamp's: no node can touch", 0);

    // Every part of the body hangs from the clamp.
    std::vector<int> parent(m.points.size());
    std::iota(parent.begin(), parent.end(), 0);
    const auto root = [&](int n) {
        while (parent[static_cast<size_t>(n)] != n)
            n = parent[static_cast<size_t>(n)] = parent[static_cast<size_t>(parent[static_cast<size_t>(n)])];
        return n;
    };
    for (size_t t = 0; t < cells; ++t) {
        const int* c = m.cell(t);
        for (int a = 1; a <= dim; ++a) parent[static_cast<size_t>(root(c[a]))] = root(c[0]);
    }
    std::vector<char> held(m.points.size(), 0);
    for (int n : m.top_nodes) held[static_cast<size_t>(root(n))] = 1;
    for (int n = 0; n < m.num_nodes(); ++n)
        if (!held[static_cast<size_t>(root(n))]) {
            const RawNode& r = raw.nodes.at(tag_of[static_cast<size_t>(n)]);
            fail(where(tag_of[static_cast<size_t>(n)], r) +
                     " is in a part of the body not "
                     "connected to the clamp (a free part would have no equilibrium)",
                 r.line);
        }

    finish_mesh(m, contact_facets);
    // Above by more than round-off of the body's size: a rotated mesh puts a clamp edge that
    // lies on the contact face one ulp above it.
    const double size = std::max({m.x_max - m.x_min, m.y_max - m.y_min, m.z_max - m.z_min});
    if (!(m.clamp_height() > 1e-6 * size)) {
        Text msg;
        msg << "the clamp group's highest node (y = " << m.clamp_y << " m) is not above the contact "
            << "group's lowest (y = " << m.contact_y << " m) by more than 1e-6 of the body's size (" << size
            << " m): the foundation lies below the contact "
            << "group and the clamp drives the body from above (are \"contact\" and \"clamp\" "
            << "swapped?)";
        fail(msg.str(), 0);
    }
    for (size_t i = 0; i < m.contact_nodes.size(); ++i)
        if (!(m.contact_shares[i] > 0)) {
            const long tag = tag_of[static_cast<size_t>(m.contact_nodes[i])];
            fail(where(tag, raw.nodes.at(tag)) + " of the contact group carries no " + w.extent +
                     " of "
                     "the foundation (its contact " +
                     w.facets +
                     " stand perpendicular to it, or it is on none): "
                     "put it in no contact " +
                     (dim == 2 ? "line" : "surface") +
                     ", or give the contact "
                     "boundary some extent along the foundation",
                 raw.nodes.at(tag).line);
        }
    return m;
}

}  // namespace contactbody
