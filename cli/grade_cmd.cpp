#include "cli/grade_cmd.h"

#include <ostream>

#include "cli/exit_code.h"
#include "present/grade_report.h"
#include "present/staged_dir.h"
#include "present/worksheets.h"
#include "teach/grade.h"

namespace collide {

int run_grade(const GradeOptions& opt, std::ostream& out, std::ostream& err) {
    return cli::run_command(err, [&] {
        const AnswerKey key = read_answer_key(opt.key);
        const std::vector<Mark> marks = grade_answers(key, opt.answers);
        const std::string tables = grade_tables(key, marks);
        if (!opt.out_dir.empty()) {
            StagedDirectory staged(opt.out_dir, opt.force);
            const auto& tmp = staged.begin();
            write_text_file(tmp / "marks.csv", marks_csv(marks));
            write_text_file(tmp / "report.html", grade_report_html(key, marks, opt.answers));
            staged.commit();
        }
        out << tables;
        if (!opt.out_dir.empty())
            out << "wrote " << opt.out_dir << "/marks.csv and " << opt.out_dir << "/report.html\n";
        return 0;
    });
}

}  // namespace collide
