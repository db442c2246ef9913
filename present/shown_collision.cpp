#include "present/shown_collision.h"

namespace collide {

std::vector<CollisionPick> figure_picks(const Lesson* lesson) {
    std::vector<CollisionPick> picks;
    if (lesson)
        for (const LessonFigure& f : lesson->figures) picks.push_back({f.ia, f.ib, f.collision, false, f.touching});
    return picks;
}

std::vector<RecordOptions::Keep> figure_keeps(const Lesson* lesson) {
    std::vector<RecordOptions::Keep> keep;
    if (lesson)
        for (const LessonFigure& f : lesson->figures) keep.push_back({f.ia, f.ib, f.collision});
    return keep;
}

}  // namespace collide
