#include "resource_start_values.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "util/c_file.hpp"

namespace contactbody::fmu {

namespace {

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

}  // namespace

std::string start_values_path(const char* resource_location) {
    const std::string folder = resources_directory(resource_location);
    return folder.empty() ? "" : folder + "start_values.txt";
}

std::string resources_directory(const char* resource_location) {
    if (!resource_location) return "";
    std::string uri = resource_location;
    const std::string scheme = "file:";
    if (uri.compare(0, scheme.size(), scheme) != 0) return "";
    std::string path = uri.substr(scheme.size());
    if (path.compare(0, 2, "//") == 0) path = path.substr(2);  // file://host/path, host empty
    std::string decoded;
    for (size_t i = 0; i < path.size(); ++i) {
        if (path[i] == '%' && i + 2 < path.size() && hex_digit(path[i + 1]) >= 0 &&
            hex_digit(path[i + 2]) >= 0) {
            decoded += static_cast<char>(16 * hex_digit(path[i + 1]) + hex_digit(path[i + 2]));
            i += 2;
        } else {
            decoded += path[i];
        }
    }
    // file:///C:/dir on Windows: the path is C:/dir
    if (decoded.size() > 2 && decoded[0] == '/' && std::isalpha(static_cast<unsigned char>(decoded[1])) &&
        decoded[2] == ':')
        decoded = decoded.substr(1);
    if (!decoded.empty() && decoded.back() != '/') decoded += '/';
    return decoded;
}

std::vector<std::pair<std::string, std::string>> read_start_values(const std::string& path) {
    std::vector<std::pair<std::string, std::string>> out;
    if (path.empty()) return out;
    const File file = open_file(path, "rb");
    if (!file) return out;  // no file: the FMU's own start values
    std::string content;
    char buffer[4096];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0;) content.append(buffer, n);
    if (std::ferror(file.get())) throw std::runtime_error("resources/start_values.txt: cannot read " + path);
    int number = 0;
    for (size_t start = 0; start < content.size();) {
        const size_t end = std::min(content.find('\n', start), content.size());
        const std::string text = trim(content.substr(start, end - start));
        start = end + 1;
        ++number;
        if (text.empty() || text[0] == '#') continue;
        const auto eq = text.find('=');
        if (eq == std::string::npos || trim(text.substr(0, eq)).empty())
            throw std::runtime_error("resources/start_values.txt, line " + std::to_string(number) +
                                     ": expected 'name = value', got '" + text + "'");
        out.emplace_back(trim(text.substr(0, eq)), trim(text.substr(eq + 1)));
    }
    return out;
}

}  // namespace contactbody::fmu
