// `collide worksheet --format moodle` (docs/commands/worksheet.md, "Moodle"): the students'
// sheets as Moodle XML questions, DIR/moodle.xml, for Moodle's question bank import. Each
// question is present/platform_questions.h's (shared with the QTI package).
//
// A category per lesson ("$course$/top/Collide worksheets/TITLE (ID)"), under it a category per
// question of the sheet ("Question K"), holding one question per student variant, so that a
// quiz's "random question" from that category gives each student one variant:
//   numerical    a number: the engine's value, the absolute tolerance marking_allowance(|value|,
//                tolerance) (teach/answers.h, the rule of every face), the unit (multiplier 1)
//                and the others of teach/units.h with Moodle's multipliers (km/h: 3.6); units
//                optional (a bare number is taken in the unit)
//   cloze        a vector: one NUMERICAL field per component, each with the allowance divided by
//                sqrt(components) (an answer within it in every component is within the rule)
//   multichoice  a choice question: single answer, fraction 100 for the right option, each
//                option's reason as its feedback
//   essay        an explain question: the model answer as information for graders
// Every question's text holds the student's givens and, in 2D, the figure of their set-up (an
// SVG file of the question, @@PLUGINFILE@@); its general feedback the worked example of each
// collision the sheet asks about. HTML goes in CDATA; everything else is escaped.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scenario/lesson.h"
#include "teach/worksheet.h"

namespace collide {

// The whole file for the lessons and their sheets (sheets[k] are lessons[k]'s).
std::string moodle_xml(const std::vector<Lesson>& lessons, const std::vector<std::vector<StudentSheet>>& sheets,
                       std::uint64_t seed);

}  // namespace collide
