// The questions of a lesson's pages: where each goes on the student's page, how it is asked
// (options, a place to commit an answer, room to write when printed) and its answer, folded.
// The script that opens an answer once the student commits one is here too.
#include "present/site_questions.h"

#include <sstream>
#include <string>
#include <vector>

#include "teach/html.h"
#include "teach/notation.h"

namespace collide::site {

using html::escape;
using html::math;
using html::paragraphs;

// The page's questions, answered by the student: choosing an option, or typing an answer and
// pressing "Check", commits it and opens its answer (a prediction's: in "Check your
// predictions", below the animation); a number is marked against the engine's within the
// question's tolerance. Once every question of "Check yourself" is committed, the worked example
// opens too. Without scripts every answer and the worked example open with one click
// (<details>). Nothing is fetched.
const char* kQuestionScript = R"(<script>
(function () {
  var worked = document.getElementById('worked');
  function committed(li) { li.classList.add('committed'); }
  function openAnswer(li) {
    var id = li.getAttribute('data-answer-at');
    var d = id ? document.getElementById(id) : li.querySelector('details.answer');
    if (d) d.open = true;
    committed(li);
    var all = document.querySelectorAll('section.check-yourself ol.questions > li');
    var done = 0;
    all.forEach(function (q) { if (q.classList.contains('committed')) done++; });
    if (worked && all.length && done === all.length) worked.open = true;
  }
  function numbers(text) {
    var m = text.replace(/\u2212/g, '-').match(/[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?/g);
    return m ? m.map(Number) : [];
  }
  document.querySelectorAll('li[data-q]').forEach(function (li) {
    var mark = li.querySelector('.mark');
    var say = function (text, cls) { if (mark) { mark.textContent = text; mark.className = 'mark ' + (cls || ''); } };
    li.querySelectorAll('input[type=radio]').forEach(function (r) {
      r.addEventListener('change', function () {
        if (li.hasAttribute('data-answer-at')) {
          say('Kept: watch, then check it below the animation.');
        } else {
          var right = r.value === li.getAttribute('data-correct');
          say(right ? 'Right: read why below.' : 'Not this one: read why below.', right ? 'right' : 'wrong');
        }
        var k = document.getElementById(li.getAttribute('data-answer-at') || '');
        var chosen = k && k.querySelector('.chosen');
        if (chosen) chosen.textContent = 'You predicted (' + r.value + '). ';
        openAnswer(li);
      });
    });
    var button = li.querySelector('button.check-answer');
    if (!button) return;
    button.addEventListener('click', function () {
      var field = li.querySelector('.answer-in');
      var text = field ? field.value : '';
      if (!/\S/.test(text)) { say('Write your answer first.'); return; }
      var want = li.getAttribute('data-value');
      if (want && !li.hasAttribute('data-answer-at')) {
        var a = JSON.parse(want), got = numbers(text), tol = parseFloat(li.getAttribute('data-tolerance'));
        if (got.length !== a.length) {
          say(a.length > 1 ? 'Give ' + a.length + ' numbers, the components (' + a.length + 'D), then check.' : 'Give one number.');
          return;
        }
        var d2 = 0, n2 = 0;
        for (var i = 0; i < a.length; i++) { d2 += (got[i] - a[i]) * (got[i] - a[i]); n2 += a[i] * a[i]; }
        var ok = Math.sqrt(d2) <= tol * Math.sqrt(n2) + 1e-9;
        say(ok ? 'Right, within the tolerance: compare your working below.' : 'Not within the tolerance: see the answer below.', ok ? 'right' : 'wrong');
      } else if (li.hasAttribute('data-answer-at')) {
        say('Kept: watch, then check it below the animation.');
        var k2 = document.getElementById(li.getAttribute('data-answer-at'));
        var c2 = k2 && k2.querySelector('.chosen');
        if (c2) c2.textContent = 'You predicted ' + text + '. ';
      } else {
        say('Compare with the model answer below.');
      }
      openAnswer(li);
    });
  });
})();
</script>
)";

// Where a question goes on the student's page: a prediction before the figures, "Check
// yourself" (numbers and choices about the lesson's own run) after the worked example, "What
// if" (why-questions and numbers of a changed scene) last.
Place place_of(const LessonQuestion& q) {
    if (q.kind == QuestionKind::predict) return Place::predict;
    if (q.kind == QuestionKind::explain || !q.what_if.empty()) return Place::what_if;
    return Place::check;
}

// The options of a choice (or predict) question: numbered, each a radio button on screen so a
// student can choose by keyboard; printed, the numbers stay for circling one.
std::string choices_html(const LessonQuestion& q, std::size_t qi) {
    std::ostringstream o;
    o << "<ul class=\"choices\">\n";
    for (std::size_t k = 0; k < q.choices.size(); ++k)
        o << "<li><label><input type=\"radio\" name=\"q" << qi + 1 << "\" value=\"" << option_number(k)
          << "\"> <span class=\"letter\">(" << option_number(k) << ")</span> " << math(q.choices[k])
          << "</label></li>\n";
    o << "</ul>\n";
    return o.str();
}

// The same options as a plain list (the teacher's page: nothing to choose).
std::string options_html(const LessonQuestion& q) {
    std::ostringstream o;
    o << "<ul class=\"choices\">\n";
    for (std::size_t k = 0; k < q.choices.size(); ++k)
        o << "<li><span class=\"letter\">(" << option_number(k) << ")</span> " << math(q.choices[k]) << "</li>\n";
    o << "</ul>\n";
    return o.str();
}

namespace {
// The full stop a sentence that ends with `text` still needs ("" when it ends with one).
std::string full_stop(const std::string& text) {
    const std::size_t end = text.find_last_not_of(" \n");
    return end != std::string::npos && std::string(".!?").find(text[end]) != std::string::npos ? "" : ".";
}
}  // namespace

// A question's answer: the engine's number, the right option with every option's reason, or
// the model answer; then why.
std::string answer_html(const LessonQuestion& q, const LessonAnswer* a, const LessonAnswer* own) {
    std::ostringstream o;
    if (q.has_choices()) {
        o << "<p><span class=\"chosen\"></span><span class=\"answer\">Option "
          << option_number(static_cast<std::size_t>(q.correct - 1)) << ".</span></p>\n<ul class=\"reasons\">\n";
        for (std::size_t k = 0; k < q.choices.size(); ++k) {
            const bool right = static_cast<int>(k) + 1 == q.correct;
            o << "<li class=\"" << (right ? "right" : "wrong") << "\"><span class=\"letter\">(" << option_number(k)
              << ")</span> <em>" << (right ? "Right" : "Wrong") << ":</em> " << math(q.reasons[k]) << "</li>\n";
        }
        o << "</ul>\n";
        if (!q.explain.empty()) o << "<p>" << math(q.explain) << "</p>\n";
    } else if (q.kind == QuestionKind::explain) {
        o << paragraphs(q.answer);
    } else if (own) {
        // Asked with the check values: the lesson's working is for its own numbers.
        o << "<p><span class=\"chosen\"></span><span class=\"answer\">" << math(a ? a->text : "?")
          << "</span> with the numbers above.</p>\n<p class=\"own-working\">With the lesson's own numbers (the run "
             "you watched) it is "
          << math(own->text) << (q.explain.empty() ? "" : ": " + math(q.explain)) << full_stop(q.explain) << "</p>\n";
    } else {
        o << "<p><span class=\"chosen\"></span><span class=\"answer\">" << math(a ? a->text : "?") << "</span>";
        if (!q.explain.empty()) o << "<br>" << math(q.explain);
        o << "</p>\n";
    }
    return o.str();
}

// The question as asked: its text and the tolerance a number is marked to.
std::string ask_html(const LessonQuestion& q) {
    std::string s = "<p class=\"ask\">" + math(q.text);
    if (shows_tolerance(q))
        s += " <span class=\"tolerance\">(to within " + escape(tolerance_text(q.tolerance)) + ")</span>";
    return s + "</p>\n";
}

// Printed, a space to write in (choices: the student circles a number instead).
std::string write_space(const LessonQuestion& q) {
    if (q.has_choices()) return "";
    return std::string("<div class=\"write-here") + (q.kind == QuestionKind::explain ? " tall" : "") +
           "\" aria-hidden=\"true\"></div>\n";
}

// On screen, where the student commits an answer: options commit when chosen; a number or a
// why-answer is typed, then "Check" (a prediction: "Keep my prediction").
std::string commit_html(const LessonQuestion& q, const LessonAnswer* a, bool prediction, int dim) {
    if (q.has_choices()) return "<p class=\"mark noprint\" role=\"status\"></p>\n";
    std::ostringstream o;
    o << "<p class=\"commit noprint\">";
    if (q.kind == QuestionKind::explain) {
        o << "<label>Your answer:<br><textarea class=\"answer-in\" rows=\"3\" cols=\"60\"></textarea></label><br>"
             "<button type=\"button\" class=\"check-answer\">Compare with the model answer</button>";
    } else {
        const bool vector = a && a->is_vector;
        o << "<label>" << (prediction ? "My prediction" : "Your answer") << ": <input type=\"text\" class=\"answer-in"
          << (prediction ? " prediction" : "") << "\" size=\"22\" inputmode=\"decimal\""
          << (vector ? std::string(" placeholder=\"components: ") + (dim == 3 ? "x, y, z" : "x, y") + "\"" : "") << ">"
          << (a && !a->unit.empty() ? " " + escape(a->unit) : "")
          << "</label> <button type=\"button\" class=\"check-answer\">" << (prediction ? "Keep my prediction" : "Check")
          << "</button>";
    }
    o << " <span class=\"mark\" role=\"status\"></span></p>\n";
    return o.str();
}

// The attributes the script marks a number with: its value (components) and tolerance.
std::string marking_attributes(const LessonQuestion& q, const LessonAnswer* a, int dim) {
    if (!q.has_quantity() || !a || !a->computed) return "";
    std::string values;
    if (a->is_vector) {
        for (int k = 0; k < std::max(dim, 1); ++k) values += (k ? "," : "") + notation::num_data(a->vector[k]);
    } else {
        values = notation::num_data(a->value);
    }
    return " data-value=\"[" + values + "]\" data-tolerance=\"" + notation::num_data(q.tolerance) + "\"";
}

// "Before you watch": the predictions, asked before the figure and the animation show what
// happens; a space to write each (or the options to choose from), no answers.
std::string predict_html(const Lesson& L, const std::vector<LessonAnswer>& answers,
                         const std::vector<std::size_t>& predict) {
    std::ostringstream o;
    o << "<section class=\"predict\" aria-labelledby=\"predict-heading\">\n<h2 id=\"predict-heading\">Before you watch"
         "</h2>\n<p class=\"note\">Predict first: write down or choose what you expect, then watch the figures "
         "and the animation, and check your prediction below them.</p>\n<ol class=\"predictions\">\n";
    for (std::size_t k = 0; k < predict.size(); ++k) {
        const std::size_t i = predict[k];
        const LessonQuestion& q = L.questions[i];
        const LessonAnswer* a = i < answers.size() ? &answers[i] : nullptr;
        o << "<li data-q=\"" << i + 1 << "\" data-answer-at=\"check-" << k + 1 << "\">" << ask_html(q)
          << (q.has_choices() ? choices_html(q, i) : "") << commit_html(q, a, true, L.scene.dimension) << write_space(q)
          << "</li>\n";
    }
    o << "</ol>\n</section>\n";
    return o.str();
}

// "Check your predictions": after the animation, each prediction's answer, folded.
std::string check_html(const Lesson& L, const std::vector<LessonAnswer>& answers,
                       const std::vector<std::size_t>& predict) {
    std::ostringstream o;
    o << "<section class=\"check\">\n<h2>Check your predictions</h2>\n<ol class=\"predictions\">\n";
    for (std::size_t k = 0; k < predict.size(); ++k) {
        const std::size_t i = predict[k];
        o << "<li><p class=\"ask\">" << math(L.questions[i].text) << "</p>\n<details id=\"check-" << k + 1
          << "\"><summary>Check your prediction</summary>\n"
          << answer_html(L.questions[i], i < answers.size() ? &answers[i] : nullptr) << "</details>\n</li>\n";
    }
    o << "</ol>\n</section>\n";
    return o.str();
}

// Questions the student answers on the page: each with its place to commit an answer, the
// answer folded below it, and printed a space to write in.
std::string questions_html(const Lesson& L, const std::vector<LessonAnswer>& answers,
                           const std::vector<std::size_t>& asked, const CheckVariant* check) {
    std::ostringstream o;
    o << "<ol class=\"questions\">\n";
    for (std::size_t i : asked) {
        const LessonQuestion& q = L.questions[i];
        const LessonAnswer* own = i < answers.size() ? &answers[i] : nullptr;
        const bool checked = check && check->answer[i];
        const LessonAnswer* a = checked ? &*check->answer[i] : own;
        o << "<li class=\"" << question_kind_name(q.kind) << (checked ? " new-numbers" : "") << "\" data-q=\"" << i + 1
          << "\"";
        if (q.has_choices()) o << " data-correct=\"" << option_number(static_cast<std::size_t>(q.correct - 1)) << "\"";
        o << marking_attributes(q, a, L.scene.dimension) << ">" << ask_html(q)
          << (q.has_choices() ? choices_html(q, i) : "") << commit_html(q, a, false, L.scene.dimension)
          << "<details class=\"answer\"><summary>Answer</summary>\n"
          << answer_html(q, a, checked ? own : nullptr) << "</details>\n"
          << write_space(q) << "</li>\n";
    }
    o << "</ol>\n";
    return o.str();
}

// "Check yourself"'s other numbers (teach/check_variant.h): the inputs that differ from the
// lesson's own, a link that sets them in the Try-it panel (`try_it`), and the questions whose
// answer these numbers leave as in the watched run (no draw changed it: on the teacher's page,
// `teacher`; the student's page does not single them out).
std::string new_numbers_html(const Lesson& L, const CheckVariant& c, bool try_it, bool teacher) {
    std::ostringstream o, rows;
    std::string query;
    for (const LessonVary& v : L.vary) {
        const auto at = c.sheet.values.find(v.name());
        if (at == c.sheet.values.end() || at->second == v.lesson_value) continue;
        rows << "<tr><td>" << math(html::vary_label(v)) << "</td><td>" << escape(notation::num_data(v.lesson_value))
             << "</td><td><strong>" << escape(notation::num_data(at->second)) << "</strong></td></tr>\n";
        query +=
            (query.empty() ? "?" : "&amp;") + html::percent_encoded(v.name()) + "=" + html::number_attr(at->second);
    }
    o << "<div class=\"new-numbers\">\n";
    if (teacher)
        o << "<p>The student's page asks the numeric questions below with these values instead of the lesson's "
             "own, so that reading the figures, which show the lesson's run, does not answer them. Each answer is "
             "for these values, with the lesson's own and its working beside it.</p>\n";
    else
        o << "<p><strong>Now with other numbers.</strong> The numeric questions below ask about the same collision "
             "with these values (the figures above show the lesson's own); everything else is as in the set-up. "
             "Work each answer out the way the worked example does (where only a run can tell, measure it in the "
             "Try-it panel with these numbers), then check it.</p>\n";
    if (rows.str().empty()) {
        o << "<p class=\"warning\">No draw of the lesson's ranges gave other values: the questions are about the "
             "run you watched.</p>\n";
    } else {
        o << "<table class=\"new-values\">\n<tr><th>input</th><th>in the run you watched</th><th>now</th></tr>\n"
          << rows.str() << "</table>\n";
    }
    if (try_it && !query.empty())
        o << "<p class=\"noprint\">Once you have checked your answers, see this run: <a href=\"index.html" << query
          << "#try-it\">the Try-it panel with these numbers</a>.</p>\n";
    for (std::size_t i : teacher ? c.same_as_watched : std::vector<std::size_t>{})
        o << "<p class=\"note\">With these numbers too, the answer to “" << math(L.questions[i].text)
          << "” is the one of the run the students watched: no draw of the lesson's ranges tried changes it.</p>\n";
    o << "</div>\n";
    return o.str();
}

}  // namespace collide::site
