#include "teach/units.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>

#include "engine/math.h"  // kPi

namespace collide {

namespace {

// Each base unit of lesson_quantity.h: its own spellings (factor 1), then the other units of
// its kind. Factors are exact definitions (1 km/h = 1/3.6 m/s; 1 rpm = 2 pi / 60 rad/s).
const std::map<std::string, std::vector<AcceptedUnit>>& table() {
    static const std::map<std::string, std::vector<AcceptedUnit>> t = {
        {"m/s", {{"m/s", 1.0}, {"m s^-1", 1.0}, {"km/h", 1.0 / 3.6}, {"cm/s", 0.01}}},
        {"N s", {{"N s", 1.0}, {"N\u00b7s", 1.0}, {"Ns", 1.0}, {"kg m/s", 1.0}, {"kN s", 1000.0}, {"mN s", 1e-3}}},
        {"kg m/s", {{"kg m/s", 1.0}, {"kg\u00b7m/s", 1.0}, {"N s", 1.0}, {"Ns", 1.0}}},
        {"kg m^2/s", {{"kg m^2/s", 1.0}, {"kg m\u00b2/s", 1.0}, {"J s", 1.0}, {"N m s", 1.0}}},
        {"J", {{"J", 1.0}, {"N m", 1.0}, {"kJ", 1000.0}, {"mJ", 1e-3}}},
        {"rad/s",
         {{"rad/s", 1.0},
          {"1/s", 1.0},
          {"s^-1", 1.0},
          {"rpm", 2.0 * kPi / 60.0},
          {"rev/s", 2.0 * kPi},
          {"deg/s", kPi / 180.0},
          {"\u00b0/s", kPi / 180.0}}},
        {"s", {{"s", 1.0}, {"ms", 1e-3}}},
        {"m", {{"m", 1.0}, {"cm", 0.01}, {"mm", 1e-3}}},
        {"N", {{"N", 1.0}, {"kN", 1000.0}}},
        {"N s/m", {{"N s/m", 1.0}, {"kg/s", 1.0}}},
    };
    return t;
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
}

}  // namespace

const std::vector<AcceptedUnit>& accepted_units(const std::string& base) {
    static std::map<std::string, std::vector<AcceptedUnit>> alone;
    if (auto it = table().find(base); it != table().end()) return it->second;
    auto it = alone.find(base);
    if (it == alone.end()) it = alone.emplace(base, std::vector<AcceptedUnit>{{base, 1.0}}).first;
    return it->second;
}

std::string normalize_unit(const std::string& unit) {
    std::string s = unit;
    replace_all(s, "\u00b2", "^2");
    replace_all(s, "\u207b\u00b9", "^-1");
    replace_all(s, "\u2212", "-");
    replace_all(s, "\u00b7", "");
    replace_all(s, "\u22c5", "");
    std::string out;
    for (const char c : s)
        if (c != ' ' && c != '\t' && c != '*' && c != '.') out += c;
    return out;
}

std::optional<double> unit_factor(const std::string& unit, const std::string& base) {
    const std::string want = normalize_unit(unit);
    for (const AcceptedUnit& u : accepted_units(base))
        if (normalize_unit(u.name) == want) return u.factor;
    return std::nullopt;
}

std::optional<double> parse_student_number(const std::string& text) {
    std::string s = text;
    replace_all(s, "\u2212", "-");
    if (s.empty()) return std::nullopt;
    const bool comma = s.find(',') != std::string::npos, point = s.find('.') != std::string::npos;
    if (comma && point) return std::nullopt;
    if (comma) replace_all(s, ",", ".");
    // Only what a written number holds: strtod would also read "inf", "nan" and hex.
    std::size_t i = 0;
    if (s[i] == '+' || s[i] == '-') ++i;
    std::size_t digits = 0, dots = 0;
    for (; i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.'); ++i)
        (s[i] == '.' ? dots : digits)++;
    if (digits == 0 || dots > 1) return std::nullopt;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        std::size_t exp_digits = 0;
        for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i) ++exp_digits;
        if (exp_digits == 0) return std::nullopt;
    }
    if (i != s.size()) return std::nullopt;
    errno = 0;
    const double x = std::strtod(s.c_str(), nullptr);
    if (errno == ERANGE || !std::isfinite(x)) return std::nullopt;
    return x;
}

}  // namespace collide
