// The students' sheets as the learning platforms' files ask them (`collide worksheet --format
// moodle,qti`, docs/commands/worksheet.md): one model of each question of each student's sheet,
// written by moodle_xml.h and qti_package.h alike, so that both show the same and mark by the
// same rule.
//
// Each student's sheet gives what every one of its questions shows first (the student, the
// givens, in 2D the figure of their set-up), the worked example of each collision the sheet
// asks about (feedback after answering), and its questions:
//   number   the engine's value, its unit, the allowance of the marking rule
//            (marking_allowance(|value|, tolerance), teach/answers.h)
//   vector   the components (2, or 3 in 3D), the unit, the allowance on the length of the
//            difference
//   choice   the options and each one's reason, the right one
//   explain  the model answer
// Text is HTML (escaped, our notation's subscripts as <sub>); every element is one of those
// QTI 2.1's XHTML subset has (present/qti_package.h qti_xhtml checks).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scenario/lesson.h"
#include "teach/worksheet.h"

namespace collide {

// The figure of a student's 2D set-up (present/worksheet_figure.h), as a file of the question.
struct PlatformFigure {
    std::string file;                 // "general-2d-student-3.svg"
    std::string svg;                  // the file: an XML declaration, then the SVG
    int width_px = 0, height_px = 0;  // as printed, at 96 dpi
};

enum class PlatformKind { number, vector, choice, explain };

struct PlatformQuestion {
    PlatformKind kind = PlatformKind::number;
    int number = 0;        // on the lesson page
    std::string name;      // "catch-up: question 1, student 001"
    std::string id;        // "collide-catch-up-q1-s1": unique, an XML name
    std::string ask_html;  // "<h4>Question 1</h4>\n<p>What impulse ...? <small>(to within 2 %)</small></p>\n"
    // number, vector:
    std::vector<double> want;  // the engine's answer: one number, or the components
    double allowance = 0.0;    // |got - want| (a vector's: the length of the difference) may be this
    std::string unit;          // "N s"; "" for a count
    // choice:
    std::vector<std::string> choices, reasons;  // HTML
    std::size_t correct = 0;                    // from 0
    // explain:
    std::string model_answer;  // HTML paragraphs
};

struct PlatformSheet {
    int student = 1;
    std::string intro_html;  // "Student K: your own numbers.", the givens
    std::optional<PlatformFigure> figure;
    std::string worked_html;  // the worked example of each collision the sheet asks about
    std::vector<PlatformQuestion> questions;
};

// Text in an XML element or attribute: &, <, >, " and ' escaped.
std::string xml_text(const std::string& s);
// A number at full precision (17 significant digits: it reads back as the same double), as
// the platforms compare with it; "0" for a zero of either sign.
std::string full_number(double x);

// One student's sheet of lesson L as the platforms ask it.
PlatformSheet platform_sheet(const Lesson& L, const StudentSheet& s);

// The figure in a question's text: the image (`src`: where the platform finds the file) and a
// line saying what it shows.
std::string platform_figure_html(const PlatformFigure& f, const std::string& src);

}  // namespace collide
