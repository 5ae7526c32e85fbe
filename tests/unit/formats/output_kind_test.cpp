// What writers declare (formats/output_kind.h): a folder's record reads back as declared, and a
// single file's mark tells a file Saltus wrote, unchanged, from one a person wrote, copied from
// another kind or edited by a single byte.

#include "saltus/formats/output_kind.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "saltus/formats/output_folder.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

TEST(FolderRecord, ReadsBackAsDeclared) {
  test::TempDir dir;
  const FolderKind kind{"paper", {"result.json", "report.md"}, {"figures"}, {"cases"}, true};
  write_folder_record(dir.path().string(), kind);
  std::string why_not;
  const FolderKind read = read_folder_record(dir.path().string(), why_not);
  EXPECT_EQ(why_not, "");
  EXPECT_EQ(read.name, kind.name);
  EXPECT_EQ(read.files, kind.files);
  EXPECT_EQ(read.image_folders, kind.image_folders);
  EXPECT_EQ(read.record_folders, kind.record_folders);
  EXPECT_TRUE(read.holds_results);
  std::filesystem::remove(dir.path() / kFolderRecordName);
  read_folder_record(dir.path().string(), why_not);
  EXPECT_NE(why_not.find("no record"), std::string::npos) << why_not;
}

const FileKind kModel = FileKind::json("body model");
const FileKind kPage = FileKind::commented("flight page", "<!--", "-->");

TEST(FileMark, AJsonFileSaltusWroteIsToldFromOneItDidNot) {
  const std::string plain = R"({"format": "saltus-model/1", "name": "junior", "mass": 61.5})";
  const std::string written = marked_text(kModel, plain);
  EXPECT_EQ(unmarked_reason(kModel, written), "");
  const nlohmann::json document = nlohmann::json::parse(written);
  EXPECT_TRUE(has_json_mark(document));
  EXPECT_EQ(without_json_mark(document), nlohmann::json::parse(plain));
  EXPECT_EQ(document[kJsonMark]["kind"], "body model");
  // Reformatting keeps it Saltus's (the digest covers the document, not its spaces) ...
  EXPECT_EQ(unmarked_reason(kModel, document.dump()), "");
  // ... a changed value does not: the file is now the user's work.
  nlohmann::json edited = document;
  edited["mass"] = 62.0;
  EXPECT_NE(unmarked_reason(kModel, edited.dump()).find("changed since"), std::string::npos);
  // Written by hand (no mark), of another kind, or not JSON: not Saltus's to replace.
  EXPECT_NE(unmarked_reason(kModel, plain), "");
  EXPECT_NE(unmarked_reason(FileKind::json("motion"), written).find("another kind"),
            std::string::npos);
  EXPECT_NE(unmarked_reason(kModel, "HIERARCHY\n"), "");
  EXPECT_NE(unmarked_reason(kModel, ""), "");
  // The mark may live where a strict schema allows extra data.
  const FileKind gltf = FileKind::json("glTF model", "/asset/extras/written_by_saltus");
  const std::string scene = marked_text(gltf, R"({"asset": {"version": "2.0"}})");
  EXPECT_EQ(unmarked_reason(gltf, scene), "");
  EXPECT_EQ(nlohmann::json::parse(scene)["asset"]["version"], "2.0");
  EXPECT_THROW(marked_text(kModel, "[1, 2]"), std::invalid_argument);
}

TEST(FileMark, ATextFileSaltusWroteEndsInItsMarkAndAnyEditBreaksIt) {
  const std::string page = "<!DOCTYPE html>\n<html><body>M7</body></html>\n";
  const std::string written = marked_text(kPage, page);
  EXPECT_EQ(written.compare(0, page.size(), page), 0) << "the mark only follows the page";
  EXPECT_NE(written.find("<!-- written by saltus: flight page "), std::string::npos) << written;
  EXPECT_EQ(unmarked_reason(kPage, written), "");
  for (std::size_t i = 0; i < page.size(); ++i) {
    std::string edited = written;
    edited[i] = static_cast<char>(edited[i] ^ 0x20);
    EXPECT_NE(unmarked_reason(kPage, edited), "") << i;
  }
  EXPECT_NE(unmarked_reason(kPage, page), "");
  EXPECT_NE(unmarked_reason(kPage, written + "<p>added</p>\n"), "");
  EXPECT_NE(unmarked_reason(FileKind::commented("MuJoCo model", "<!--", "-->"), written), "");
}

TEST(FileMark, AKindWithoutAMarkNeverCallsAFileItsOwn) {
  const FileKind bvh = FileKind::unmarked("BVH capture");
  EXPECT_EQ(marked_text(bvh, "HIERARCHY\n"), "HIERARCHY\n");
  EXPECT_NE(unmarked_reason(bvh, "HIERARCHY\n"), "");
}

}  // namespace
}  // namespace saltus
