// `collide worksheet --format qti` (docs/commands/worksheet.md, "QTI"): the students' sheets
// as an IMS QTI 2.1 content package, DIR/qti.zip, for the learning platforms that import QTI
// 2.1 (OpenOLAT, ILIAS, TAO, Canvas, Blackboard, ...). The same questions as moodle.xml
// (present/platform_questions.h), one assessmentItem per question and student:
//   imsmanifest.xml    IMS Content Packaging 1.1 (the QTI 2.1 profile): a resource per item
//                      (imsqti_item_xmlv2p1; its file and, in 2D, a dependency on its figure),
//                      per figure (webcontent) and per lesson's test (imsqti_test_xmlv2p1)
//   ID/qK-sS.xml       question K of student S of lesson ID (namespace imsqti_v2p1):
//     (a number and a vector right only when every field is answered: <not><isNull>)
//     number   a textEntryInteraction, baseType float; right when |got - want| <= allowance
//              (<equal toleranceMode="absolute">, marking_allowance of teach/answers.h: the
//              rule of every face), the unit written after the field
//     vector   a textEntryInteraction per component; right when the length of the difference
//              is within the allowance (the sum of the squared differences against its square:
//              the rule of `collide grade`)
//     choice   a choiceInteraction, one option; each option's reason as modalFeedback
//     explain  an extendedTextInteraction; the model answer as a rubricBlock for the scorer
//              (not shown to candidates)
//     each     the student's givens and, in 2D, the figure of their set-up (<img> of the SVG
//              file beside it) in the itemBody; the worked example as modalFeedback once
//              answered; SCORE (0 or 1; explain: for a grader to set) and MAXSCORE 1
//   ID/student-S.svg   the figure of student S's set-up (2D lessons)
//   ID/test.xml        an assessmentTest of the lesson: a section per question, each drawing
//                      one of its variants (selection select="1"), SCORE the sum of the items'
//                      (a lesson whose sheet asks no question has no test and no item)
// Files in that order, lesson by lesson (questions, then students, as in moodle.xml); the same
// seed gives the same bytes (present/stored_zip.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "present/stored_zip.h"
#include "scenario/lesson.h"
#include "teach/worksheet.h"

namespace collide {

// The package's files, in the archive's order (sheets[k] are lessons[k]'s).
std::vector<ZipEntry> qti_package_files(const std::vector<Lesson>& lessons,
                                        const std::vector<std::vector<StudentSheet>>& sheets, std::uint64_t seed);
// qti.zip: those files, stored.
std::string qti_package(const std::vector<Lesson>& lessons, const std::vector<std::vector<StudentSheet>>& sheets,
                        std::uint64_t seed);

// Our HTML (teach/html.h, present/platform_questions.h) as the XHTML a QTI 2.1 itemBody holds:
// void elements closed (<img .../>), a table's rows in a <tbody>, only QTI's elements and
// attributes (class, id; img's src, alt (both required), width, height; td's and th's colspan,
// rowspan, ...).
// Throws std::logic_error for any other element, attribute or character reference (&nbsp;)
// and for tags that do not nest: a program error, never dropped quietly.
std::string qti_xhtml(const std::string& html);

}  // namespace collide
