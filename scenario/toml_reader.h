// Typed, located access to TOML tables for our input files. Every error names the file, the
// line and column, the full key ("a.mass") and what was expected.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "scenario/input_error.h"
#include "engine/math.h"

namespace collide {

// Input files are at most this long (collision, scenario and lesson files, GUI scripts,
// standard input).
constexpr std::size_t kMaxInputBytes = 1 << 20;  // 1 MiB

// Reads a whole input file ("-" is stdin, shown as "<stdin>" in messages). Throws InputError
// when it cannot be read, is a directory, holds a NUL byte (not text) or is longer than
// kMaxInputBytes: the limit is checked while reading, so a stream without end (/dev/zero,
// `yes |`, a FIFO) is refused after at most 1 MiB and the first 64 KiB holding a NUL.
std::string read_input_file(const std::string& path, std::string* display_name);
// The same for an open stream, `name` the file name in messages.
std::string read_bounded(std::istream& in, const std::string& name);
// Parses TOML with the checks every input gets: text (no NUL bytes), not empty, at most 1 MiB.
// `name` is the file name used in messages. Throws InputError.
toml::table parse_toml_text(const std::string& text, const std::string& name);

// A number as a person writes it: 0.5, -2, 1e+300.
std::string show(double x);

// Closest candidate by edit distance, or "" if none is close ("did you mean" hints).
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

class TableReader {
public:
    // prefix: the table's own key ("a" for [a], "" for the root).
    TableReader(const toml::table& table, std::string file, std::string prefix);

    // Rejects keys not in `allowed`, with a "did you mean" hint.
    void allow_only(const std::vector<std::string>& allowed) const;
    // Rejects a key that is known but means nothing here (e.g. "w" in 1D).
    void forbid(const std::string& key, const std::string& why) const;

    bool has(const std::string& key) const;
    std::string full_key(const std::string& key) const;
    SourcePos pos(const std::string& key) const;  // the key's value, or the table
    SourcePos table_pos() const;

    // Finite number with |x| <= 1e12 (integers accepted). `what` describes it in errors.
    std::optional<double> number(const std::string& key, const std::string& what) const;
    double required_number(const std::string& key, const std::string& what) const;
    std::optional<long long> integer(const std::string& key, const std::string& what) const;
    std::optional<bool> boolean(const std::string& key) const;
    std::optional<std::string> string(const std::string& key, const std::string& what) const;
    // A string shown as one line (a title): no line breaks, tabs or other control characters
    // (C0, DEL, C1: an ESC or OSC sequence would act on the terminal it is printed to).
    std::optional<std::string> line(const std::string& key, const std::string& what) const;
    // Array of exactly n numbers (n = 0: of any length but empty).
    std::optional<std::vector<double>> numbers(const std::string& key, std::size_t n, const std::string& what) const;
    // 3x3 array of arrays of numbers.
    std::optional<Mat3> matrix3(const std::string& key, const std::string& what) const;
    const toml::node* node(const std::string& key) const;
    std::optional<TableReader> table(const std::string& key) const;
    // The [[key]] tables in order, each named key[1], key[2], ... in messages; none when the
    // key is absent. Refuses a key that is not an array of tables.
    std::vector<TableReader> tables(const std::string& key) const;

    [[noreturn]] void fail(const std::string& key, const std::string& message) const;
    const std::string& file() const { return file_; }
    const std::string& prefix() const { return prefix_; }  // "a" for [a], "body[2]" for a [[body]]

private:
    double checked_number(const toml::node& n, const std::string& key, const std::string& what) const;

    const toml::table& table_;
    std::string file_;
    std::string prefix_;
};

// A vector of dimension dim, zero-padded to 3D: 1D a number, 2D [x, y], 3D [x, y, z].
std::optional<Vec3> read_vec(const TableReader& t, const std::string& key, int dim, const std::string& unit);
constexpr double kMinSize = 1e-12;  // smallest mass or length accepted (kg, m)

// A required number > 0 and >= kMinSize (masses, lengths).
double read_positive(const TableReader& t, const std::string& key, const std::string& what);
// A 3x3 inertia tensor a rigid body can have: symmetric, positive definite, I1 + I2 >= I3.
void check_inertia(const TableReader& t, const std::string& key, const Mat3& I);
// The required `dimension` key: 1, 2 or 3.
int read_dimension(const TableReader& t);
// A body's angular velocity: 2D a number (counter-clockwise +) as the z component, 3D [x, y, z];
// zero when absent or in 1D.
Vec3 read_spin(const TableReader& t, int dim);
// A 3D orientation quaternion [w, x, y, z], normalised (identity when absent).
Quat read_orientation(const TableReader& t);
// Refuses keys of another dimension with a message that says so (angle in 3D, orientation in
// 2D, w in 1D), not "unknown key".
void forbid_other_dimension_keys(const TableReader& t, int dim);
// One of `options` (with a "did you mean" hint); `fallback` when absent ("" = required).
std::string read_choice(const TableReader& t, const std::string& key, const std::vector<std::string>& options,
                        const std::string& what, const std::string& fallback);

}  // namespace collide
