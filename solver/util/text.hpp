// Text without iostreams: messages built piece by piece, numbers written and read with '.' as
// the decimal point. <sstream> and <fstream> link the C++ library's locale machinery into
// every binary that uses them (docs/building.md, "iostreams and `std::filesystem`").
#pragma once

#include <string>
#include <string_view>
#include <type_traits>

namespace contactbody {

// x as an ostream with this precision writes it (printf's %.<precision>g), '.' as the decimal
// point whatever the C locale the host set.
std::string format_number(double x, int precision = 6);

// The whole of `text`, blanks around it allowed, as a finite number ('.' the decimal point,
// an optional sign); false if it is anything else (the value of x is then unspecified).
bool parse_number(std::string_view text, double& x);

// A message built as with std::ostringstream: msg << "got " << x << " m".
class Text {
public:
    Text& operator<<(std::string_view s) {
        text_ += s;
        return *this;
    }
    template <class T, std::enable_if_t<std::is_arithmetic_v<T>, int> = 0>
    Text& operator<<(T x) {
        if constexpr (std::is_same_v<T, char>)
            text_ += x;
        else if constexpr (std::is_floating_point_v<T>)
            text_ += format_number(static_cast<double>(x), precision_);
        else
            text_ += std::to_string(x);  // bool as 0 or 1, as an ostream writes it
        return *this;
    }
    // Significant digits of the numbers that follow (6 unless set, as an ostream).
    void precision(int digits) { precision_ = digits; }
    const std::string& str() const { return text_; }

private:
    std::string text_;
    int precision_ = 6;
};

}  // namespace contactbody
