// Reading a student's answer and the class's CSV (`collide grade`, teach/grade.h) and the
// units it converts (teach/units.h): numbers as students write them, units by their
// definitions, RFC 4180's quoting, and the slips computed from the key's values.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/math.h"
#include "scenario/input_error.h"
#include "teach/grade.h"
#include "teach/units.h"

namespace collide {
namespace {

TEST(StudentNumber, PointCommaSignExponent) {
    EXPECT_EQ(parse_student_number("1.25"), 1.25);
    EXPECT_EQ(parse_student_number("1,25"), 1.25);
    EXPECT_EQ(parse_student_number("-0,5"), -0.5);
    EXPECT_EQ(parse_student_number("\u22120.5"), -0.5);  // the true minus
    EXPECT_EQ(parse_student_number("+2"), 2.0);
    EXPECT_EQ(parse_student_number("1.5e-3"), 1.5e-3);
    EXPECT_EQ(parse_student_number("1,5E3"), 1500.0);
    EXPECT_EQ(parse_student_number(".5"), 0.5);
    for (const char* bad : {"", "-", "1.2.3", "1,2.3", "abc", "inf", "nan", "0x10", "1e", "2 3", "1e999"})
        EXPECT_FALSE(parse_student_number(bad).has_value()) << bad;
}

TEST(StudentAnswer, NumberThenUnit) {
    auto a = read_student_answer(" 1,25 km/h ");
    ASSERT_TRUE(a);
    EXPECT_EQ(a->numbers, std::vector<double>{1.25});
    EXPECT_EQ(a->unit, "km/h");
    a = read_student_answer("3J");  // no space
    ASSERT_TRUE(a);
    EXPECT_EQ(a->numbers, std::vector<double>{3.0});
    EXPECT_EQ(a->unit, "J");
    a = read_student_answer("2e3 J");
    ASSERT_TRUE(a);
    EXPECT_EQ(a->numbers, std::vector<double>{2000.0});
    a = read_student_answer("(0.9, -0.1) m/s");
    ASSERT_TRUE(a);
    EXPECT_TRUE(a->is_vector);
    EXPECT_EQ(a->numbers, (std::vector<double>{0.9, -0.1}));
    EXPECT_EQ(a->unit, "m/s");
    a = read_student_answer("(0,9; 0,1; 2)");
    ASSERT_TRUE(a);
    EXPECT_EQ(a->numbers, (std::vector<double>{0.9, 0.1, 2.0}));
    EXPECT_EQ(a->unit, "");
    for (const char* bad : {"about 3", "(1)", "(1, 2", "(a, b)", "m/s"}) EXPECT_FALSE(read_student_answer(bad)) << bad;
}

TEST(Units, Definitions) {
    EXPECT_DOUBLE_EQ(*unit_factor("km/h", "m/s"), 1000.0 / 3600.0);
    EXPECT_DOUBLE_EQ(*unit_factor("kJ", "J"), 1000.0);
    EXPECT_DOUBLE_EQ(*unit_factor("rpm", "rad/s"), 2.0 * kPi / 60.0);
    EXPECT_DOUBLE_EQ(*unit_factor("N\u00b7s", "N s"), 1.0);
    EXPECT_DOUBLE_EQ(*unit_factor("Ns", "N s"), 1.0);
    EXPECT_DOUBLE_EQ(*unit_factor("kg m/s", "N s"), 1.0);  // the same dimension
    EXPECT_DOUBLE_EQ(*unit_factor("kg m\u00b2/s", "kg m^2/s"), 1.0);
    EXPECT_FALSE(unit_factor("J", "m/s"));
    EXPECT_FALSE(unit_factor("ms", "m/s"));  // milliseconds, not metres per second
    EXPECT_EQ(accepted_units("m/s").front().name, "m/s");
    EXPECT_EQ(accepted_units("").size(), 1u);
}

TEST(Csv, Rfc4180) {
    const auto r = parse_csv(
        "\xef\xbb\xbfstudent,question,answer\r\n1,2,\"1,5 m/s\"\r\n\r\n3,4,\"say \"\"hi\"\"\nthere\"\n5,6,7", "a.csv");
    ASSERT_EQ(r.size(), 4u);
    EXPECT_EQ(r[0].fields[0], "student");
    EXPECT_EQ(r[1].line, 2);
    EXPECT_EQ(r[1].fields[2], "1,5 m/s");
    EXPECT_EQ(r[2].line, 4);  // the blank line 3 is no record
    EXPECT_EQ(r[2].fields[2], "say \"hi\"\nthere");
    EXPECT_EQ(r[3].line, 6);  // the quoted line break counts
    EXPECT_EQ(r[3].fields, (std::vector<std::string>{"5", "6", "7"}));
    EXPECT_THROW(parse_csv("1,2,\"3\n", "a.csv"), InputError);
    EXPECT_THROW(parse_csv("1,2,3\"x\"\n", "a.csv"), InputError);
    EXPECT_THROW(parse_csv("1,2,\"3\"x\n", "a.csv"), InputError);
}

TEST(Slips, FromTheKeysValues) {
    KeyAnswer a;
    a.quantity = "impulse";
    a.unit = "N s";
    a.value = {1.5};
    a.tolerance = 0.02;
    KeyStudent s;
    s.restitution = 0.5;
    const auto slips = likely_slips(a, s);
    ASSERT_EQ(slips.size(), 4u);
    EXPECT_EQ(slips[0].name, "the sign flipped");
    EXPECT_DOUBLE_EQ(slips[0].value[0], -1.5);
    EXPECT_EQ(slips[1].name, "without the factor (1 + e)");
    EXPECT_DOUBLE_EQ(slips[1].value[0], 1.0);
    EXPECT_DOUBLE_EQ(slips[2].value[0], 2.0);  // 2 for (1 + e)
    EXPECT_DOUBLE_EQ(slips[3].value[0], -1.0);
    // e = 1: (1 + e) is 2, "as if elastic" is the right answer and no slip.
    s.restitution = 1.0;
    for (const Slip& sl : likely_slips(a, s)) EXPECT_EQ(sl.name.find("elastic"), std::string::npos) << sl.name;
    EXPECT_EQ(likely_slips(a, s).size(), 3u);
    // Without e in the key: the sign alone.
    s.restitution.reset();
    EXPECT_EQ(likely_slips(a, s).size(), 1u);
    a.quantity = "energy_lost";
    a.unit = "J";
    EXPECT_EQ(likely_slips(a, s).back().name, "without the 1/2 of the kinetic energy");
}

}  // namespace
}  // namespace collide
