// bccmis::JsonWriter (bccmis/json_writer.h): the layout every --json report
// has, written out by hand here.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>

#include "bccmis/json_writer.h"

namespace bccmis {
namespace {

TEST(JsonWriter, MembersElementsAndNesting) {
  JsonWriter w;
  w.begin_object().member("name", "a \"b\"\n").member("n", std::size_t{12}).member("x", 0.1).member("ok", true);
  w.key("none").null().key("list").begin_array().value(-3).value(2.5).begin_object().end_object().end_array();
  w.key("empty").begin_array().end_array().key("fixed").json_value("45.000000").end_object();
  EXPECT_EQ(w.str(),
            "{\"name\": \"a \\\"b\\\"\\n\", \"n\": 12, \"x\": 0.1, \"ok\": true, \"none\": null, "
            "\"list\": [-3, 2.5, {}], \"empty\": [], \"fixed\": 45.000000}");
}

TEST(JsonWriter, NumbersHaveNineSignificantDigits) {
  EXPECT_EQ(JsonWriter::number(1.0 / 3), "0.333333333");
  EXPECT_EQ(JsonWriter::number(123456789012.0), "1.23456789e+11");
  EXPECT_EQ(JsonWriter::number(-0.0051174943), "-0.0051174943");
  JsonWriter w;
  w.begin_array().value(2.0).value(1e-300).end_array();
  EXPECT_EQ(w.str(), "[2, 1e-300]");
}

}  // namespace
}  // namespace bccmis
