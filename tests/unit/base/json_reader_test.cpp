// Path-tracking JSON access (base/json_reader.h): every error names the file and the JSON pointer
// of the bad value, and the pointers it builds are RFC 6901 pointers — nlohmann's own pointer
// lookup finds the same value through them.

#include "saltus/base/json_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "support/temp_path.h"

namespace saltus {
namespace {

/// Runs `f`, which must throw InputError; returns it.
template <typename F>
InputError input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", "", "");
}

const nlohmann::json kDocument = nlohmann::json::parse(R"({
  "keyframes": [{"time": 0.5, "rotations": {"knee/l": [1, 0, 0, 0]}}, {"time": "late"}],
  "a~b": {"n": 3, "x": 1.5, "flag": true, "nothing": null},
  "vector": [1, 2]
})");

TEST(JsonNode, BuildsPointersThatNlohmannResolvesToTheSameValue) {
  const JsonNode root(kDocument, "m.json");
  EXPECT_EQ(root.path(), "");
  EXPECT_EQ(root.path_or_root(), "/");
  const JsonNode knee = root.at("keyframes").at(0).at("rotations").at("knee/l");
  EXPECT_EQ(knee.path(), "/keyframes/0/rotations/knee~1l");
  EXPECT_EQ(kDocument.at(nlohmann::json::json_pointer(knee.path())), knee.value());
  const JsonNode n = root.at("a~b").at("n");
  EXPECT_EQ(n.path(), "/a~0b/n");
  EXPECT_EQ(kDocument.at(nlohmann::json::json_pointer(n.path())), 3);
  for (const auto& [key, member] : root.at("a~b").members())
    EXPECT_EQ(kDocument.at(nlohmann::json::json_pointer(member.path())), member.value()) << key;
  EXPECT_EQ(json_pointer_escape("~/x/~"), "~0~1x~1~0");
}

TEST(JsonNode, ErrorsNameTheFileAndThePointerOfTheBadValue) {
  const JsonNode root(kDocument, "m.json");
  const InputError late = input_error([&] { root.at("keyframes").at(1).at("time").as_double(); });
  EXPECT_EQ(late.file(), "m.json");
  EXPECT_EQ(late.json_path(), "/keyframes/1/time");
  EXPECT_EQ(late.problem(), "expected a number, found string");
  EXPECT_EQ(input_error([&] { root.at("keyframes").at(1).at("rotations"); }).problem(),
            "missing field \"rotations\"");
  EXPECT_EQ(input_error([&] { root.at("keyframes").at(2); }).json_path(), "/keyframes");
  EXPECT_EQ(input_error([&] { root.at("vector").as_doubles(3); }).problem(),
            "expected 3 numbers, found 2");
  EXPECT_EQ(input_error([&] { root.at("vector").as_vector3(); }).json_path(), "/vector");
  EXPECT_EQ(input_error([&] { root.at("a~b").at("x").as_int(); }).problem(),
            "expected an integer, found number");
  EXPECT_EQ(input_error([&] { root.at("a~b").at("flag").as_double(); }).problem(),
            "expected a number, found boolean");
  EXPECT_EQ(input_error([&] { root.at("vector").at("x"); }).problem(),
            "expected an object, found array");
  EXPECT_EQ(input_error([&] { root.fail("bad"); }).json_path(), "/");
  // A value that JSON text cannot hold but a document built in memory can.
  const nlohmann::json nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(input_error([&] { JsonNode(nan, "mem").as_double(); }).problem(),
            "expected a finite number");
}

TEST(JsonNode, ReadsValuesAndOptionalMembers) {
  const JsonNode root(kDocument, "m.json");
  EXPECT_EQ(root.at("a~b").at("n").as_int(), 3);
  EXPECT_EQ(root.at("a~b").at("x").as_double(), 1.5);
  EXPECT_EQ(root.at("keyframes").size(), 2u);
  EXPECT_EQ(root.at("vector").as_double_array(), (std::vector<double>{1, 2}));
  EXPECT_TRUE(root.has("vector"));
  EXPECT_FALSE(root.has("time"));
  EXPECT_FALSE(root.at("a~b").find("nothing"));  // null counts as absent
  EXPECT_FALSE(root.at("a~b").find("missing"));
  ASSERT_TRUE(root.at("a~b").find("n"));
  EXPECT_EQ(root.at("a~b").find("n")->path(), "/a~0b/n");
}

TEST(ReadJsonFile, NamesTheFileAndWhereTheSyntaxBreaks) {
  const std::string path = test::temp_path("json-reader-test.json").string();
  std::ofstream(path) << "{\n  \"a\": 1,\n  \"b\": [1, 2,, 3]\n}\n";
  const InputError syntax = input_error([&] { read_json_file(path); });
  EXPECT_EQ(syntax.file(), path);
  EXPECT_NE(syntax.problem().find("invalid JSON"), std::string::npos) << syntax.what();
  EXPECT_NE(syntax.problem().find("line 3"), std::string::npos) << syntax.what();
  std::ofstream(path) << "{\"a\": [1, 2]}";
  EXPECT_EQ(read_json_file(path), nlohmann::json::parse("{\"a\": [1, 2]}"));
  std::filesystem::remove(path);
  EXPECT_EQ(input_error([&] { read_json_file(path); }).problem(), "cannot open file for reading");
}

}  // namespace
}  // namespace saltus
