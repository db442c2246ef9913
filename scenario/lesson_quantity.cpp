#include "scenario/lesson_quantity.h"

#include <algorithm>

namespace collide {

namespace {

constexpr bool same_text(const char* a, const char* b) {
    while (*a && *a == *b) ++a, ++b;
    return *a == *b;
}

// Whether each name is given to one quantity only.
constexpr bool names_distinct() {
    for (std::size_t i = 0; i < quantity_count(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (same_text(quantity_name(static_cast<Quantity>(i)), quantity_name(static_cast<Quantity>(j))))
                return false;
    return true;
}

}  // namespace

// The names are the file format: the reader maps each back to one quantity.
static_assert(names_distinct(), "two quantities with one name in quantity_info()");

const std::vector<Quantity>& all_quantities() {
    static const std::vector<Quantity> all = [] {
        std::vector<Quantity> v;
        for (std::size_t i = 0; i < quantity_count(); ++i) v.push_back(static_cast<Quantity>(i));
        return v;
    }();
    return all;
}

std::optional<Quantity> quantity_named(const std::string& name) {
    for (Quantity q : all_quantities())
        if (name == quantity_name(q)) return q;
    return std::nullopt;
}

const std::vector<std::string>& lesson_quantities() {
    // Sorted: the reader's "expected one of" list and its closest-name hint go in this order.
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (Quantity q : all_quantities()) v.push_back(quantity_name(q));
        std::sort(v.begin(), v.end());
        return v;
    }();
    return names;
}

}  // namespace collide
