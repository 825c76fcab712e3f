#include "util/text.hpp"

#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace contactbody {

std::string format_number(double x, int precision) {
    char buffer[64];
    const int n = std::snprintf(buffer, sizeof buffer, "%.*g", precision, x);
    std::string s(buffer, n > 0 ? static_cast<size_t>(n) : 0);
    // printf follows LC_NUMERIC, which a host may have set (setlocale(LC_ALL, "")).
    const char* point = std::localeconv()->decimal_point;
    if (point && *point && std::strcmp(point, ".") != 0)
        if (const size_t at = s.find(point); at != std::string::npos) s.replace(at, std::strlen(point), ".");
    return s;
}

bool parse_number(std::string_view text, double& x) {
    const char* blanks = " \t\r\n\f\v";
    const size_t first = text.find_first_not_of(blanks);
    if (first == std::string_view::npos) return false;
    text = text.substr(first, text.find_last_not_of(blanks) - first + 1);
    // from_chars takes no '+' (an ostream's reading did)
    if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, x);
    return error == std::errc() && stop == end && std::isfinite(x);
}

}  // namespace contactbody
