// The units a student may write an answer in (`collide grade`, and the units Moodle accepts in
// `collide worksheet --format moodle`): for each unit our lessons answer in (scenario/
// lesson_quantity.h: "m/s", "N s", "J", "rad/s", ...), the ways of writing it and the other
// units of the same kind with their factors (km/h, kJ, rpm, ...). The one table of them.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace collide {

// A unit a student may write for an answer whose unit is `base`: `x name` is `x * factor base`.
struct AcceptedUnit {
    std::string name;  // as written: "km/h"
    double factor;     // to the base unit: km/h -> 1 / 3.6 (m/s)
};

// The units accepted for answers in `base` (a unit of scenario/lesson_quantity.h, e.g. "m/s"):
// the base itself first (factor 1), its other spellings ("N·s", "Ns", "kg m/s" for "N s"),
// then the other units of its kind. An unknown base or "" (a count): just the base.
const std::vector<AcceptedUnit>& accepted_units(const std::string& base);

// The factor that turns a value written in `unit` into `base` (`unit` compared after
// normalize_unit), or none when `unit` is not one accepted for `base`.
std::optional<double> unit_factor(const std::string& unit, const std::string& base);

// A unit as compared: spaces, '*', '·', '⋅' and '.' between symbols removed, '²' and '^2' alike,
// "⁻¹" as "^-1": "N·s" -> "Ns", "kg m²/s" -> "kgm^2/s".
std::string normalize_unit(const std::string& unit);

// A number as a student writes it: an optional sign ('-', '+' or the true minus U+2212),
// digits with a decimal point or a decimal comma ("1,25"; a number holding both is refused),
// an optional exponent ("1.2e-3", "1,2E3"). Returns none for anything else.
std::optional<double> parse_student_number(const std::string& text);

}  // namespace collide
