// Path-tracking JSON access (base/json_reader.h): every error names the file and the JSON pointer
// of the bad value, and the pointers it builds are RFC 6901 pointers — nlohmann's own pointer
// lookup finds the same value through them.
//
// Hardening (issue 16 items 5-7): duplicate keys, numbers beyond double's range, ill-formed
// UTF-8 and file names, files that are not regular or too large, all InputError naming the file
// (and the JSON pointer); unknown keys with the nearest valid one suggested.

#include "saltus/base/json_reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "support/cli_runner.h"
#include "support/input_errors.h"
#include "support/temp_path.h"

namespace saltus {
namespace {

/// Runs `f`, which must throw InputError; returns it.
template <typename F>
InputError input_error(F f) {
  if (const std::optional<InputError> e = test::thrown_input_error(f)) return *e;
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
  // The reason follows (issue 16: a failure names the system's reason).
  EXPECT_EQ(
      input_error([&] { read_json_file(path); }).problem().rfind("cannot open file for reading", 0),
      0u);
}

// Hardening (issue 16).
namespace hardening {

namespace fs = std::filesystem;

using test::input_error;

TEST(JsonReader, DuplicateKeysAreRefusedAtTheirPointer) {
  EXPECT_EQ(input_error([] { parse_json_text(R"({"a": 1, "a": 2})", "f.json"); }),
            "f.json: /a: the key \"a\" appears twice in this object (JSON readers disagree on "
            "which one counts; keep one)");
  const std::string nested = input_error([] {
    parse_json_text(R"({"k": [{"r": {"x": 1}}, {"r": {"knee_l": 1, "y": [1, 2], "knee_l": 2}}]})",
                    "m.json");
  });
  EXPECT_EQ(nested.rfind("m.json: /k/1/r/knee_l: the key \"knee_l\" appears twice", 0), 0u)
      << nested;
  // Equal keys in different objects are fine, and so is the parsed document.
  const nlohmann::json ok = parse_json_text(R"({"a": {"b": 1}, "c": [{"b": 2}, {"b": 3}]})", "f");
  EXPECT_EQ(ok["c"][1]["b"], 3);
  EXPECT_EQ(ok, nlohmann::json::parse(R"({"a": {"b": 1}, "c": [{"b": 2}, {"b": 3}]})"));
}

TEST(JsonReader, ParsesLikeNlohmannOnGeneratedDocuments) {
  // The tracking parser builds the same document as nlohmann's own on a seeded family.
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> number(-1e6, 1e6);
  for (int trial = 0; trial < 50; ++trial) {
    nlohmann::json doc = nlohmann::json::object();
    for (int i = 0; i < 20; ++i) {
      nlohmann::json value;
      switch (rng() % 5) {
        case 0:
          value = number(rng);
          break;
        case 1:
          value = static_cast<int>(rng() % 1000) - 500;
          break;
        case 2:
          value = {number(rng), nullptr, "x", true};
          break;
        case 3:
          value = {{"inner", {1, 2, {{"deep", "é"}}}}};
          break;
        default:
          value = nlohmann::json::array();
          break;
      }
      doc["key" + std::to_string(rng() % 40)] = value;
    }
    EXPECT_EQ(parse_json_text(doc.dump(), "g.json"), doc);
  }
}

TEST(JsonReader, NumbersBeyondDoubleAreBadInputWithTheirPointer) {
  // Issue 16 item 6: `1e400` ended as exit 1, "internal error: number overflow".
  const std::string message =
      input_error([] { parse_json_text("{\"takeoff\": {\"com_position\": [1e400, 1, 0]}}", "m"); });
  EXPECT_NE(message.find("m: /takeoff/com_position/0: number 1e400 is out of range"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("line 1, column"), std::string::npos) << message;
  EXPECT_NE(input_error([] { parse_json_text("[-1e309]", "m"); }).find("m: /0:"),
            std::string::npos);
  // Underflow is not an error: 1e-400 is 0.
  EXPECT_EQ(parse_json_text("[1e-400]", "m")[0].get<double>(), 0.0);
}

TEST(JsonReader, SyntaxEncodingAndDepthErrorsNameTheFile) {
  EXPECT_NE(input_error([] {
              parse_json_text("{\"a\": [1, }", "f.json");
            }).find("f.json: invalid JSON: parse error at line 1"),
            std::string::npos);
  const std::string utf8 = input_error([] { parse_json_text("{\"a\": \"\xC3\x28\"}", "f.json"); });
  EXPECT_NE(utf8.find("UTF-8"), std::string::npos) << utf8;
  EXPECT_TRUE(is_valid_utf8(utf8)) << "the message itself must be printable UTF-8";
  std::string deep;
  for (int i = 0; i < 100; ++i)
    deep += "[";
  EXPECT_NE(input_error([&] { parse_json_text(deep, "f.json"); }).find("nested deeper than 64"),
            std::string::npos);
}

TEST(JsonReader, FilesThatAreNotRegularOrTooLargeAreRefusedUnread) {
  // Issue 16 item 7: /dev/zero was read until memory ran out.
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(input_error([] { read_json_file("/dev/zero"); }),
            "/dev/zero: is not a regular file (a device, pipe or socket); Saltus reads model "
            "and motion files only");
  test::TempDir dir;
  EXPECT_EQ(input_error([&] { read_json_file(dir.path().string()); }),
            dir.path().string() + ": is a folder, not a file");
  // A named pipe with no writer: refused at once, not waited on.
  const std::string fifo = dir / "pipe.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(input_error([&] { read_json_file(fifo); }).find("not a regular file"),
            std::string::npos);
  const std::string big = dir / "big.json";
  { std::ofstream(big) << "[]"; }
  fs::resize_file(big, kMaxJsonFileBytes + 1);  // sparse
  EXPECT_NE(input_error([&] { read_json_file(big); }).find("at most 64 MiB"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5);
  EXPECT_NE(input_error([&] {
              read_json_file(dir / "missing.json");
            }).find("missing.json: cannot open file for reading: No such file"),
            std::string::npos);
}

TEST(JsonReader, FileNamesMustBeUtf8) {
  test::TempDir dir;
  const std::string name = dir / "m\xFF.json";
  test::write_text(name, "{}");
  const std::string message = input_error([&] { read_json_file(name); });
  EXPECT_NE(message.find("m\\xFF.json: the file name is not valid UTF-8"), std::string::npos)
      << message;
  EXPECT_TRUE(is_valid_utf8(message));
}

TEST(JsonReader, UnknownKeysAreRefusedWithTheNearestValidOne) {
  const nlohmann::json doc = nlohmann::json::parse(R"({"format": 1, "tolerence": {}})");
  const JsonNode root(doc, "m.json");
  EXPECT_EQ(input_error([&] {
              root.require_keys_within({"format", "tolerances", "takeoff"});
            }),
            "m.json: /tolerence: unknown field \"tolerence\" (did you mean \"tolerances\"?); "
            "allowed here: \"format\", \"tolerances\", \"takeoff\"");
  EXPECT_EQ(input_error([&] { root.require_keys_within({"format", "tolerence"}); }), "");
  EXPECT_EQ(nearest_name("mas", {"name", "mass", "com"}), "mass");
  EXPECT_EQ(nearest_name("KNEE_L", {"knee_l", "knee_r"}), "knee_l");
  EXPECT_EQ(nearest_name("zebra", {"mass", "com"}), "");
}

TEST(JsonReader, RangesAndIntegers) {
  const nlohmann::json doc = nlohmann::json::parse(R"({"m": 1e308, "i": 4294967296, "n": -3})");
  const JsonNode root(doc, "f");
  EXPECT_EQ(input_error([&] { root.at("m").as_double_within(0, 1000, "kg"); }),
            "f: /m: 1e+308 kg is outside the plausible range [0, 1000] kg");
  EXPECT_NE(input_error([&] { root.at("i").as_int(); }).find("too large"), std::string::npos);
  EXPECT_EQ(root.at("n").as_int(), -3);
}

}  // namespace hardening

}  // namespace
}  // namespace saltus
