#include "teach/check_variant.h"

#include <cmath>

namespace collide {

bool marked_right(const LessonAnswer& copied, const LessonAnswer& want, double tolerance) {
    // The page's script: |got - want| <= tolerance |want| + 1e-9 (vectors by their lengths).
    const double d = want.is_vector ? (copied.vector - want.vector).norm() : std::abs(copied.value - want.value);
    const double n = want.is_vector ? want.vector.norm() : std::abs(want.value);
    return d <= marking_allowance(n, tolerance);
}

CheckVariant check_variant(const Lesson& L, const std::vector<LessonAnswer>& own) {
    CheckVariant best;
    std::size_t best_equal = 0;
    for (int draw = 1; draw <= kCheckDraws; ++draw) {
        // The first draw's refusal is the lesson's (its ranges cannot answer); a later one only
        // ends the search for a better draw.
        StudentSheet s;
        try {
            s = draw_student(L, kCheckSeed, draw);
        } catch (const InputError&) {
            if (draw == 1) throw;
            break;
        }
        std::vector<std::size_t> equal;
        for (std::size_t k = 0; k < s.asked.size(); ++k) {
            const std::size_t i = s.asked[k];
            const LessonQuestion& q = L.questions[i];
            if (q.has_quantity() && i < own.size() && marked_right(own[i], s.answers[k], q.tolerance))
                equal.push_back(i);
        }
        if (draw == 1 || equal.size() < best_equal) {
            best.sheet = std::move(s);
            best.same_as_watched = equal;
            best_equal = equal.size();
        }
        if (best_equal == 0) break;
    }
    best.answer.assign(L.questions.size(), std::nullopt);
    for (std::size_t k = 0; k < best.sheet.asked.size(); ++k)
        if (L.questions[best.sheet.asked[k]].has_quantity()) best.answer[best.sheet.asked[k]] = best.sheet.answers[k];
    return best;
}

}  // namespace collide
