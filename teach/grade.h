// Marking a class's answers against a worksheet's key (`collide grade`, docs/commands/grade.md):
// key.json (present/worksheets.h) read back, the answers' CSV read (RFC 4180: student,
// question, answer), each answer marked with the question's tolerance (teach/answers.h
// marking_allowance) after its unit is converted (teach/units.h), and the wrong ones compared
// with the slips a student is likely to make (the sign flipped, the impulse without (1 + e),
// ...), computed from the key's values.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace collide {

// One numeric question of one student's sheet, as key.json gives it.
struct KeyAnswer {
    int question = 0;           // its number on the lesson page
    std::string text;           // the question as asked ("What impulse J does B receive?"); "" in a
                                // key written before key.json had it
    std::string quantity;       // "impulse"
    std::vector<double> value;  // one number, or a vector's 2 or 3 components
    bool is_vector = false;
    std::string unit;        // "N s"; "" for a count
    double tolerance = 0.0;  // relative
};

struct KeyStudent {
    int student = 0;
    std::map<std::string, double> values;  // the values drawn
    std::optional<double> restitution;     // e, when one e holds for every collision of the run
    std::vector<KeyAnswer> answers;
};

struct AnswerKey {
    std::string file;  // as given, for messages
    std::string lesson;
    std::vector<KeyStudent> students;
    const KeyStudent* student(int number) const;
};

// Reads key.json. Throws InputError naming the file and the field for anything missing or of
// the wrong type (a key written before tolerances were in it is refused, saying so).
AnswerKey read_answer_key(const std::string& path);

// A likely slip: the value a student gets by it.
struct Slip {
    std::string name;  // "the sign flipped"
    std::vector<double> value;
};
// The slips for one answer, each differing from the right value by more than its tolerance:
// the sign flipped; for an impulse, without (1 + e) and with 2 for (1 + e) (when the key gives
// e); for an energy, without the 1/2; for a spin, in degrees/s and in rpm written as rad/s.
std::vector<Slip> likely_slips(const KeyAnswer& answer, const KeyStudent& student);

// One answer marked.
struct Mark {
    int student = 0, question = 0;
    int line = 0;             // its line in the CSV; 0 when not answered
    std::string given;        // the answer as written
    bool answered = false;    // a non-empty answer
    bool right = false;       // within the tolerance
    std::vector<double> got;  // the answer in the key's unit (empty when not comparable)
    const KeyAnswer* key = nullptr;
    std::string note;  // "no unit: taken as N s", "km/h converted to m/s", "J is not a unit of m/s", ...
    std::string slip;  // the likely slip a wrong answer matches, or ""
};

// The marks of the students the CSV names, one for every numeric question of each (those
// without a row: not answered), ordered by student and question. Throws InputError naming
// the CSV, the line and the field for a bad row (or the CSV alone when it has no row): a record without 3 fields, a student or
// question the key does not have, a (student, question) given twice, an answer that is not a
// number (or vector) with an optional unit, a unit not known. Reads no CSV before the key.
std::vector<Mark> grade_answers(const AnswerKey& key, const std::string& csv_path);
// The same from the CSV's text (`name` for messages).
std::vector<Mark> grade_answers_text(const AnswerKey& key, const std::string& csv_text, const std::string& name);

// The answer split into number(s) and unit as `collide grade` reads it (for tests):
// "1,25 km/h" -> {1.25}, "km/h"; "(0.9, 0.1) m/s" -> {0.9, 0.1}, "m/s". None when it is not one.
struct ReadAnswer {
    std::vector<double> numbers;
    bool is_vector = false;
    std::string unit;  // as written, trimmed; "" for none
};
std::optional<ReadAnswer> read_student_answer(const std::string& text);

// The RFC 4180 records of a CSV text, each with the line it starts on (1-based). Throws
// InputError(name, line) for a quote left open or text after a closing quote.
struct CsvRecord {
    int line = 0;
    std::vector<std::string> fields;
};
std::vector<CsvRecord> parse_csv(const std::string& text, const std::string& name);

}  // namespace collide
