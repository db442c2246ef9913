// Formulas written once, printed two ways: plain Unicode text for the terminal and LaTeX for
// Markdown. A formula is written in the text notation (v_pa, ω_a, I_a⁻¹, ×, ·) and converted to
// LaTeX mechanically; numbers, units and prose carry both forms themselves.
#pragma once

#include <string>

#include "engine/math.h"

namespace collide::notation {

struct F {
    std::string txt, tex;
};
inline F operator+(F a, const F& b) { return {a.txt + b.txt, a.tex + b.tex}; }

// Text notation -> LaTeX: Greek letters, ×, ·, ⁻¹, ², ᵀ, ′, subscripts v_pa -> v_{pa}.
std::string to_tex(const std::string& text);

// Text notation -> the renderer's rich text (render/draw2d.h): subscripts v_pa -> v_{pa}.
std::string to_rich(const std::string& text);

// A formula in the text notation.
inline F f(const std::string& text) { return {text, to_tex(text)}; }
// Prose inside a formula line (upright in LaTeX).
F words(const std::string& text);
// A unit after a number: " m/s" / "\,\mathrm{m/s}".
F unit(const std::string& u);
// A number to 6 significant digits ("-0" shown as "0"; 1e-07 as 1\times10^{-7} in LaTeX;
// 10 000 to 1 000 000 written out, "20000"); 4 for students (StudentNumbers).
F num(double x);
std::string num_text(double x);
// An answer for students: 4 significant digits ("-0" shown as "0"). Full precision stays in
// the data files and in key.json.
std::string num_answer(double x);
// A number in running text for students (the site's sentences, a worksheet key): `digits`
// significant figures (printf %.Ng), "0" for |x| < 1e-12, a true minus sign (U+2212).
std::string sig_text(double x, int digits);
// A leading '-' as a true minus sign (U+2212): numbers set in running text.
std::string true_minus(std::string s);
// A vector of a problem's dimension in running text, each component written by `number`:
// 1D "x", 2D "(x, y)", 3D "(x, y, z)".
std::string components_text(const Vec3& v, int dim, std::string (*number)(double));
// Ten significant digits (printf %.10g, "-0" kept): the data files (data.csv, events.csv)
// and numbers quoted back in messages.
std::string num_data(double x);
// Numbers for students (the site, worksheets, a lesson's worked example) while one of these
// lives on the thread: num(), vec(), spin(), mat() and num_text() give 4 significant digits,
// and show as 0 what is floating-point noise of an exact event or below the precision shown: a
// vector's component below 5e-5 of its largest (it rounds to 0 at the vector's 4 digits), and
// any value below 1e-8 in SI units (1e-7 of 0.1 m, 0.1 m/s, 0.1 kg: a hundred times below the
// smallest a lesson is about, a domino's 1e-6 N s; the island solver leaves 1e-9 m/s on boxes
// at rest). `collide solve` keeps 6 digits for checking.
class StudentNumbers {
public:
    StudentNumbers();
    ~StudentNumbers();
    StudentNumbers(const StudentNumbers&) = delete;
    StudentNumbers& operator=(const StudentNumbers&) = delete;

private:
    bool was_;
};

// A vector of the problem's dimension: 1D a number, 2D (x, y), 3D (x, y, z).
F vec(const Vec3& v, int dim);
// An angular velocity: 2D the z component, 3D the vector.
F spin(const Vec3& w, int dim);
// A matrix of the problem's dimension (2D: the upper-left 2x2).
F mat(const Mat3& m, int dim);

}  // namespace collide::notation
