#include "scenario/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include <sys/stat.h>

#include <Eigen/Eigenvalues>

namespace collide {

namespace {

constexpr std::size_t kMaxFileBytes = kMaxInputBytes;  // collision and scenario files are small
constexpr double kMaxMagnitude = 1e12;                 // beyond this, squares lose all precision

SourcePos to_pos(const toml::source_region& r) {
    return SourcePos{static_cast<int>(r.begin.line), static_cast<int>(r.begin.column)};
}

const char* type_name(const toml::node& n) {
    switch (n.type()) {
        case toml::node_type::table: return "a table";
        case toml::node_type::array: return "an array";
        case toml::node_type::string: return "a string";
        case toml::node_type::integer: return "an integer";
        case toml::node_type::floating_point: return "a number";
        case toml::node_type::boolean: return "a boolean";
        case toml::node_type::date: return "a date";
        case toml::node_type::time: return "a time";
        case toml::node_type::date_time: return "a date-time";
        default: return "nothing";
    }
}

// What a value of the wrong type is, quoting a string: a student who wrote mass = "2 kg" or
// static = "yes" sees their text, not only "a string". `fix` says what to write instead.
std::string got(const toml::node& n, const std::string& fix) {
    if (const auto* s = n.as_string()) return "got the string '" + s->get() + "'; " + fix;
    return std::string("got ") + type_name(n);
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                              std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string show(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    // Names a physics student may well type for our keys.
    static const std::vector<std::pair<std::string, std::string>> aliases = {{"velocity", "v"},
                                                                             {"vel", "v"},
                                                                             {"omega", "w"},
                                                                             {"angular_velocity", "w"},
                                                                             {"spin", "w"},
                                                                             {"pos", "position"},
                                                                             {"x", "position"},
                                                                             {"m", "mass"},
                                                                             {"e", "restitution"},
                                                                             {"cor", "restitution"},
                                                                             {"mu", "friction"},
                                                                             {"n", "normal"},
                                                                             {"I", "inertia"},
                                                                             {"quaternion", "orientation"},
                                                                             {"rotation", "orientation"},
                                                                             {"q", "orientation"},
                                                                             {"theta", "angle"},
                                                                             {"dim", "dimension"},
                                                                             {"contact", "point"},
                                                                             {"fixed", "static"},
                                                                             {"immovable", "static"},
                                                                             {"cube", "box"},
                                                                             {"ball", "sphere"},
                                                                             {"circle", "disc"},
                                                                             {"disk", "disc"},
                                                                             {"square", "rectangle"},
                                                                             {"rect", "rectangle"},
                                                                             {"stick", "rod"},
                                                                             {"bar", "rod"},
                                                                             {"ground", "plane"},
                                                                             {"wall", "plane"}};
    for (const auto& [alias, key] : aliases)
        if (word == alias && std::find(candidates.begin(), candidates.end(), key) != candidates.end()) return key;
    std::string best;
    std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const std::string& c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_d) {
            best_d = d;
            best = c;
        }
    }
    return best;
}

std::string read_bounded(std::istream& in, const std::string& name) {
    std::string text;
    char chunk[1 << 16];
    while (in) {
        in.read(chunk, sizeof chunk);
        const auto got = static_cast<std::size_t>(in.gcount());
        if (std::memchr(chunk, '\0', got))
            throw InputError(name, {}, "", "not a text file (it contains NUL bytes); expected TOML");
        if (text.size() + got > kMaxFileBytes)
            throw InputError(name, {}, "",
                             "the input is too large: longer than 1 MiB (stopped reading there); input files are "
                             "limited to 1 MiB");
        text.append(chunk, got);
    }
    if (in.bad()) throw InputError(name, {}, "", "cannot read the file");
    return text;
}

std::string read_input_file(const std::string& path, std::string* display_name) {
    const std::string name = path == "-" ? "<stdin>" : path;
    *display_name = name;
    if (path == "-") return read_bounded(std::cin, name);
    // A directory opens as a stream on Linux (its "size" the largest offset there is).
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw InputError(name, {}, "", "is a directory; expected a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name, {}, "", "cannot open the file (does it exist?)");
    return read_bounded(in, name);
}

toml::table parse_toml_text(const std::string& text, const std::string& name) {
    if (text.size() > kMaxFileBytes)
        throw InputError(name, {}, "", "the input is too large; input files are limited to 1 MiB");
    if (text.find('\0') != std::string::npos)
        throw InputError(name, {}, "", "not a text file (it contains NUL bytes); expected TOML");
    if (text.find_first_not_of(" \t\r\n") == std::string::npos)
        throw InputError(name, {}, "", "the file is empty; expected a TOML description");
    try {
        return toml::parse(text, name);
    } catch (const toml::parse_error& err) {
        std::string what(err.description());
        // toml++ reports an unterminated string as the line break it runs into.
        if (what.find("control characters") != std::string::npos) what += " (is a closing quote missing?)";
        throw InputError(name, to_pos(err.source()), "", "TOML syntax error: " + what);
    }
}

TableReader::TableReader(const toml::table& table, std::string file, std::string prefix)
    : table_(table), file_(std::move(file)), prefix_(std::move(prefix)) {}

std::string TableReader::full_key(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }

SourcePos TableReader::table_pos() const { return to_pos(table_.source()); }

SourcePos TableReader::pos(const std::string& key) const {
    if (const toml::node* n = table_.get(key)) return to_pos(n->source());
    // A key missing from the root table has no place in the file; one missing from [a] points
    // at the table's header.
    return prefix_.empty() ? SourcePos{} : table_pos();
}

void TableReader::fail(const std::string& key, const std::string& message) const {
    throw InputError(file_, pos(key), key.empty() ? prefix_ : full_key(key), message);
}

void TableReader::allow_only(const std::vector<std::string>& allowed) const {
    for (auto&& [k, v] : table_) {
        const std::string key(k.str());
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        std::string msg = "unknown key";
        const std::string hint = closest_match(key, allowed);
        if (!hint.empty()) msg += " (did you mean '" + hint + "'?)";
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        msg += "; allowed here: " + list;
        throw InputError(file_, to_pos(k.source()), full_key(key), msg);
    }
}

void TableReader::forbid(const std::string& key, const std::string& why) const {
    if (has(key)) fail(key, why);
}

bool TableReader::has(const std::string& key) const { return table_.get(key) != nullptr; }

const toml::node* TableReader::node(const std::string& key) const { return table_.get(key); }

double TableReader::checked_number(const toml::node& n, const std::string& key, const std::string& what) const {
    if (!n.is_number())
        throw InputError(file_, to_pos(n.source()), full_key(key),
                         "expected " + what + ", " + got(n, "write the number without quotes or units"));
    // An integer beyond 2^53 has no exact double, and toml++ gives none: taken as the nearest
    // (then out of range below), not as NaN ("got nan" puzzled whoever wrote 10^16).
    const double x =
        n.is_integer() ? static_cast<double>(n.as_integer()->get()) : n.value<double>().value_or(std::nan(""));
    if (!std::isfinite(x))
        throw InputError(file_, to_pos(n.source()), full_key(key),
                         "expected " + what + ", got " + show(x) + " (values must be finite)");
    if (std::abs(x) > kMaxMagnitude)
        throw InputError(file_, to_pos(n.source()), full_key(key),
                         "value " + show(x) +
                             " is out of range (|value| <= 1e12; choose units "
                             "that keep numbers moderate)");
    return x;
}

std::optional<double> TableReader::number(const std::string& key, const std::string& what) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    return checked_number(*n, key, what);
}

double TableReader::required_number(const std::string& key, const std::string& what) const {
    if (auto x = number(key, what)) return *x;
    fail("", "missing key '" + key + "' (" + what + ")");
}

std::optional<long long> TableReader::integer(const std::string& key, const std::string& what) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    // "got a number" would puzzle whoever wrote 2.0 or 1.5: show the value and what to write.
    if (const auto* x = n->as_floating_point(); x && std::isfinite(x->get())) {
        const double v = x->get() + 0.0;  // -0.0 shows as 0
        if (v != std::floor(v)) fail(key, "expected " + what + ", got " + show(v) + ", which is not a whole number");
        if (std::abs(v) < 1e6)
            fail(key, "expected " + what + ", got " + show(v) + ".0; write " + show(v) + ", without the decimal point");
    }
    if (!n->is_integer()) fail(key, "expected " + what + ", " + got(*n, "write the whole number without quotes"));
    return n->value<long long>();
}

std::optional<bool> TableReader::boolean(const std::string& key) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    if (!n->is_boolean()) fail(key, "expected true or false, " + got(*n, "write true or false without quotes"));
    return n->value<bool>();
}

std::optional<std::string> TableReader::string(const std::string& key, const std::string& what) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    if (!n->is_string()) fail(key, "expected " + what + ", got " + type_name(*n));
    return n->value<std::string>();
}

std::optional<std::string> TableReader::line(const std::string& key, const std::string& what) const {
    const std::optional<std::string> s = string(key, what);
    if (!s) return s;
    for (std::size_t i = 0; i < s->size(); ++i) {
        const auto c = static_cast<unsigned char>((*s)[i]);
        // U+0080..U+009F (C1, ESC's 8-bit forms) are C2 80..C2 9F in UTF-8.
        const bool c1 = c == 0xC2 && i + 1 < s->size() && static_cast<unsigned char>((*s)[i + 1]) >= 0x80 &&
                        static_cast<unsigned char>((*s)[i + 1]) <= 0x9F;
        if (c < 0x20 || c == 0x7F || c1)
            fail(key, "expected " + what +
                          " on one line, without control characters (line breaks, tabs, escape "
                          "sequences), got '" +
                          one_line(*s) + "'");
    }
    return s;
}

std::optional<std::vector<double>> TableReader::numbers(const std::string& key, std::size_t count,
                                                        const std::string& what) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    const toml::array* arr = n->as_array();
    if (!arr) fail(key, "expected " + what + ", got " + type_name(*n));
    if (count == 0 && arr->empty()) fail(key, "expected " + what + " (at least one number), got none");
    if (count != 0 && arr->size() != count)
        fail(key, "expected " + what + " (" + std::to_string(count) + " numbers), got " + std::to_string(arr->size()) +
                      (arr->size() == 1 ? " number" : " numbers"));
    std::vector<double> out;
    for (const toml::node& el : *arr) out.push_back(checked_number(el, key, what));
    return out;
}

std::optional<Mat3> TableReader::matrix3(const std::string& key, const std::string& what) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    const toml::array* rows = n->as_array();
    if (!rows || rows->size() != 3) fail(key, "expected " + what);
    Mat3 m;
    for (int i = 0; i < 3; ++i) {
        const toml::array* row = rows->get(i)->as_array();
        if (!row || row->size() != 3)
            throw InputError(file_, to_pos(rows->get(i)->source()), full_key(key),
                             "expected " + what + "; row " + std::to_string(i + 1) + " is not 3 numbers");
        for (int j = 0; j < 3; ++j) m(i, j) = checked_number(*row->get(j), key, what);
    }
    return m;
}

std::optional<TableReader> TableReader::table(const std::string& key) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    const toml::table* t = n->as_table();
    if (!t) fail(key, std::string("expected a table [") + key + "], got " + type_name(*n));
    return TableReader(*t, file_, full_key(key));
}

std::vector<TableReader> TableReader::tables(const std::string& key) const {
    std::vector<TableReader> out;
    const toml::node* list = table_.get(key);
    if (!list) return out;
    const toml::array* items = list->as_array();
    if (!items) fail(key, "expected [[" + key + "]] tables");
    for (std::size_t i = 0; i < items->size(); ++i) {
        const toml::table* t = items->get(i)->as_table();
        const std::string entry = key + "[" + std::to_string(i + 1) + "]";
        if (!t) fail(key, entry + " is not a table; write [[" + key + "]]");
        out.emplace_back(*t, file_, full_key(entry));
    }
    return out;
}

// A vector of the problem's dimension, zero-padded to 3D: 1D a number, 2D [x, y], 3D [x, y, z].
std::optional<Vec3> read_vec(const TableReader& t, const std::string& key, int dim, const std::string& unit) {
    if (dim == 1) {
        if (auto x = t.number(key, "a number (" + unit + ")")) return Vec3(*x, 0, 0);
        return std::nullopt;
    }
    const std::string what = dim == 2 ? "[x, y] in " + unit : "[x, y, z] in " + unit;
    auto v = t.numbers(key, static_cast<std::size_t>(dim), what);
    if (!v) return std::nullopt;
    return Vec3((*v)[0], (*v)[1], dim == 3 ? (*v)[2] : 0.0);
}

double read_positive(const TableReader& t, const std::string& key, const std::string& what) {
    const double x = t.required_number(key, what);
    if (!(x > 0)) t.fail(key, "expected " + what + " > 0, got " + show(x));
    if (x < kMinSize) t.fail(key, "too small (below 1e-12); choose units that keep numbers moderate");
    return x;
}

// Checks that a 3x3 inertia tensor is one a rigid body can have.
void check_inertia(const TableReader& t, const std::string& key, const Mat3& I) {
    const double scale = I.cwiseAbs().maxCoeff();
    if ((I - I.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale)
        t.fail(key, "the inertia tensor must be symmetric (I[i][j] == I[j][i])");
    const Vec3 lambda = Eigen::SelfAdjointEigenSolver<Mat3>(I).eigenvalues();  // ascending
    if (!(lambda[0] > 1e-12 * lambda[2]))
        t.fail(key, "the inertia tensor must be positive definite; its principal moments are " + show(lambda[0]) +
                        ", " + show(lambda[1]) + ", " + show(lambda[2]) + " kg m^2");
    if (lambda[0] + lambda[1] < lambda[2] * (1 - 1e-9))
        t.fail(key, "no rigid body has this inertia: the principal moments " + show(lambda[0]) + ", " +
                        show(lambda[1]) + ", " + show(lambda[2]) + " break I1 + I2 >= I3");
}

int read_dimension(const TableReader& t) {
    auto dim = t.integer("dimension", "1, 2 or 3");
    if (!dim) t.fail("", "missing key 'dimension' (1, 2 or 3)");
    if (*dim < 1 || *dim > 3) t.fail("dimension", "expected 1, 2 or 3, got " + std::to_string(*dim));
    return static_cast<int>(*dim);
}

Vec3 read_spin(const TableReader& t, int dim) {
    if (dim == 2) return Vec3(0, 0, t.number("w", "an angular velocity in rad/s (counter-clockwise +)").value_or(0.0));
    if (dim == 3) return read_vec(t, "w", 3, "rad/s").value_or(Vec3::Zero());
    return Vec3::Zero();
}

Quat read_orientation(const TableReader& t) {
    auto o = t.numbers("orientation", 4, "a quaternion [w, x, y, z]");
    if (!o) return Quat::Identity();
    Quat q((*o)[0], (*o)[1], (*o)[2], (*o)[3]);
    if (!(q.norm() > 1e-12)) t.fail("orientation", "a zero quaternion is no rotation");
    return q.normalized();
}

void forbid_other_dimension_keys(const TableReader& t, int dim) {
    if (dim != 3) t.forbid("orientation", "orientation (a quaternion) is for 3D; in 2D use angle");
    if (dim != 2) t.forbid("angle", "angle is for 2D; in 3D use orientation = [w, x, y, z]");
    if (dim == 1) t.forbid("w", "'w' has no meaning in 1D (bodies move on a line)");
}

std::string read_choice(const TableReader& t, const std::string& key, const std::vector<std::string>& options,
                        const std::string& what, const std::string& fallback) {
    const auto value = t.string(key, what);
    if (!value) {
        if (fallback.empty()) t.fail("", "missing key '" + key + "' (" + what + ")");
        return fallback;
    }
    if (std::find(options.begin(), options.end(), *value) != options.end()) return *value;
    std::string list;
    for (std::size_t i = 0; i < options.size(); ++i)
        list += (i == 0 ? "" : i + 1 == options.size() ? " or " : ", ") + options[i];
    std::string msg = "unknown " + what + " '" + *value + "'; expected " + list;
    const std::string hint = closest_match(*value, options);
    if (!hint.empty()) msg += " (did you mean '" + hint + "'?)";
    t.fail(key, msg);
}

}  // namespace collide
