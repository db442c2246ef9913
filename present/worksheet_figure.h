// The figure of a 2D worksheet (`collide worksheet`, docs/commands/worksheet.md): one
// student's own set-up as inline SVG, drawn from the same sheet (teach/worksheet.h) the
// givens' table and the key are written from.
//
// At the start (t = 0), to scale: every body at its position and angle, its centre and name,
// its velocity (one scale for all) and its spin (an arc, counter-clockwise positive) where not
// zero; axes through the origin and a scale bar in metres. For each collision the questions
// ask about (StudentSheet::worked, the run's own, as the key's worked example has it): the
// two bodies where they touch (dashed, where that is not where they start), the contact point
// p, the unit normal n from a into b (engine convention, /work/shared/PHYSICS.md; a fixed
// length) and r_a, r_b from each centre at the hit to p. Nothing the questions ask: no
// impulse, no velocity after.
//
// The marks carry their values for tests and tools, in scene units at full precision:
//   data-body="NAME" data-x data-y data-angle           a body at the start
//   data-body-at-hit="NAME" data-collision="K" ...       the same at collision K
//   data-point="p" data-collision="K" data-x data-y     the contact point
//   data-vector="n|r_a|r_b|v" data-x data-y data-dx data-dy (origin, components; v: m/s)
//   data-spin="NAME" data-w                              rad/s
//   data-label="TEXT" data-box="X0 Y0 X1 Y1"             a label and the box it takes (px)
#pragma once

#include <string>

#include "teach/worksheet.h"

namespace collide {

// The figure's size when printed (mm): the SVG's width and height attributes.
struct WorksheetFigure {
    std::string svg;  // "" for a lesson that is not 2D
    double width_mm = 0.0, height_mm = 0.0;
};

// `max_height_mm`: the tallest the figure may be on paper; its width is at most
// kWorksheetFigureWidthMm. `id`: unique on the page (the SVG's clip path is named by it).
constexpr double kWorksheetFigureWidthMm = 120.0;
WorksheetFigure worksheet_figure(const StudentSheet& sheet, double max_height_mm, const std::string& id);

}  // namespace collide
