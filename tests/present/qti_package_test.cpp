// present/qti_package.h's qti_xhtml: our HTML as the XHTML a QTI 2.1 itemBody holds, and the
// refusals that keep anything else out (the package itself: tests/qti, under Node).
#include "present/qti_package.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace collide {
namespace {

TEST(QtiXhtml, RowsGoInATbodyAndEmptyElementsClose) {
    EXPECT_EQ(qti_xhtml("<table class=\"givens\">\n<tr><th>a</th></tr>\n<tr><td>1</td></tr>\n</table>\n"),
              "<table class=\"givens\">\n<tbody><tr><th>a</th></tr>\n<tr><td>1</td></tr>\n</tbody></table>\n");
    EXPECT_EQ(qti_xhtml("<table><tbody><tr><td>1</td></tr></tbody></table>"),
              "<table><tbody><tr><td>1</td></tr></tbody></table>");
    EXPECT_EQ(qti_xhtml("<p><img src=\"a.svg\" alt=\"x &amp; y\" width=\"3\" height=\"4\"><br>a<br/>b</p>"),
              "<p><img src=\"a.svg\" alt=\"x &amp; y\" width=\"3\" height=\"4\"/><br/>a<br/>b</p>");
    EXPECT_EQ(qti_xhtml("<div class=\"math\">v<sub>a</sub>&#8242; &lt; 2</div><!-- a note -->"),
              "<div class=\"math\">v<sub>a</sub>&#8242; &lt; 2</div>");
}

TEST(QtiXhtml, RefusesWhatQtiDoesNotHave) {
    for (const char* bad :
         {"<svg width=\"1\"></svg>", "<p style=\"color: red\">a</p>", "<div data-x=\"1\">a</div>", "<p>a&nbsp;b</p>",
          "<p>a&times;b</p>", "<p><b>a</p></b>", "<p>a", "a</p>", "<img src=\"a\">", "<p class='a'>x</p>",
          "<button>a</button>", "<p>a<img src=\"x\" alt=\"y\"></img></p>", "<p/>", "<p class=\"a>x</p>"})
        EXPECT_THROW(qti_xhtml(bad), std::logic_error) << bad;
}

}  // namespace
}  // namespace collide
