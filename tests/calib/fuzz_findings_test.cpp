// Inputs the fuzzers found (fuzz/, docs/fuzzing.md) in the camera YAML and capture-manifest
// readers: each is refused with an InputError naming the file (and the field where there is
// one), never a crash, a hang, an unbounded allocation or undefined behaviour.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "sim/camera_model.hpp"
#include "sim/patterns.hpp"
#include "tests/test_data.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

namespace fs = std::filesystem;

const std::string kCameraMatrix =
    "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
    "   data: [ 500., 0., 320., 0., 500., 240., 0., 0., 1. ]\n";
const std::string kDistortion =
    "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n"
    "   data: [ 0.1, -0.05, 0., 0., 0. ]\n";
const std::string kCameraFile =
    "%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\n" + kCameraMatrix + kDistortion;

// Writes `text` as a camera file and expects read_yaml to refuse it naming `field`.
void expect_camera_rejected(const std::string& text, const std::string& field) {
  const fs::path path = test::temp_dir("camera_fuzz") / "camera.yaml";
  std::ofstream(path, std::ios::binary) << text;
  try {
    sim::CameraIntrinsics::read_yaml(path);
    FAIL() << "accepted: " << text;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("camera.yaml"), std::string::npos) << what;
    EXPECT_NE(what.find(field), std::string::npos) << what;
  }
}

TEST(CameraYamlFuzzFindings, AWellFormedFileStillReads) {
  const fs::path path = test::temp_dir("camera_fuzz_ok") / "camera.yaml";
  std::ofstream(path) << kCameraFile << "# from a calibration tool\n...\n";
  EXPECT_EQ(sim::CameraIntrinsics::read_yaml(path).distortion.size(), 5u);
}

TEST(CameraYamlFuzzFindings, ANulByteIsRefused) {  // OpenCV's YAML reader loops forever on it
  expect_camera_rejected(kCameraFile + std::string("x: 1\0\n", 6), "NUL");
}

TEST(CameraYamlFuzzFindings, ASecondDocumentIsRefused) {  // "- b" after "..." loops forever
  expect_camera_rejected(kCameraFile + "...\n- b\n", "one YAML document");
}

TEST(CameraYamlFuzzFindings, ContentAfterTheDocumentStartIsRefused) {  // "--- -A\nA" loops
  expect_camera_rejected("%YAML:1.0\n--- -A\nA\n", "---");
  expect_camera_rejected("%YAML:1.0\n---\n  image_width: 640\nA\n", "column 1");
}

TEST(CameraYamlFuzzFindings, XmlAndJsonAreRefused) {  // OpenCV's XML reader crashed on this
  expect_camera_rejected("<?xml si=", "YAML");
  expect_camera_rejected("{\"image_width\": 640}", "YAML");
}

TEST(CameraYamlFuzzFindings, AnAbsurdMatrixSizeIsRefusedBeforeOpenCVAllocatesIt) {
  // A non-numeric size reads as INT_MAX: OpenCV asked for 85 GB.
  expect_camera_rejected("%YAML:1.0\n---\ncamera_matrix: !!opencv-matrix\n   rows:ws: 1\n"
                         "   cols: 5\n   dt: d\n   data: [ 0.1, -0.05, 0., 0., 0. ]\n",
                         "camera_matrix");
  expect_camera_rejected("%YAML:1.0\n---\ncamera_matrix: !!opencv-matrix\n   rows: 100000\n"
                         "   cols: 100000\n   dt: d\n   data: [ 1 ]\n",
                         "camera_matrix");
}

TEST(CameraYamlFuzzFindings, ATopLevelThatIsNotAMapIsRefused) {  // OpenCV asserted isMap()
  expect_camera_rejected("%YAML:1.0\n---\n- 1\n- 2\n", "camera.yaml");
}

// The board-only manifest of the fuzz corpus, with one field changed.
nlohmann::ordered_json seed_manifest() {
  return nlohmann::ordered_json::parse(read_text_file(
      fs::path(LFD_SOURCE_DIR) / "fuzz/corpus/fuzz_capture_manifest/gen1-board-only.manifest.json"));
}

fs::path write_manifest(const nlohmann::ordered_json& j) {
  const fs::path dir = test::temp_dir("manifest_fuzz");
  fs::create_directories(dir / "patterns");
  std::ofstream(dir / "patterns" / "manifest.json") << j.dump();
  return dir;
}

void expect_manifest_rejected(const nlohmann::ordered_json& j, const std::string& field) {
  try {
    sim::read_pattern_set(write_manifest(j));
    FAIL() << "accepted a manifest with a bad " << field;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("manifest.json"), std::string::npos) << what;
    EXPECT_NE(what.find(field), std::string::npos) << what;
  }
}

TEST(CaptureManifestFuzzFindings, TheSeedManifestReads) {
  const sim::PatternSet set = sim::read_pattern_set(write_manifest(seed_manifest()));
  EXPECT_EQ(set.fringe_steps, 0);
  EXPECT_EQ(set.phase_steps, 8);
}

TEST(CaptureManifestFuzzFindings, FieldsOfTheWrongTypeAreInputErrors) {
  auto j = seed_manifest();
  j["format"] = 5;  // escaped as nlohmann's type_error
  expect_manifest_rejected(j, "format");
  j = seed_manifest();
  j["version"] = "one";
  expect_manifest_rejected(j, "version");
  j = seed_manifest();
  j["fringe_period_px"] = "wide";
  expect_manifest_rejected(j, "fringe_period_px");
  j = seed_manifest();
  j["board"]["corners_px"] = 3;
  expect_manifest_rejected(j, "board.corners_px");
}

TEST(CaptureManifestFuzzFindings, NumbersBeyondIntAreRefusedNotConverted) {
  auto j = seed_manifest();
  j["phase_steps"] = 1e300;  // converted to int: undefined behaviour
  expect_manifest_rejected(j, "phase_steps");
  j = seed_manifest();
  j["board"]["squares_x"] = 1e300;
  expect_manifest_rejected(j, "board.squares_x");
  j = seed_manifest();
  j["patterns"][0]["index"] = -1e300;
  expect_manifest_rejected(j, "patterns.index");
  j = seed_manifest();
  j["board"]["marker_px"] = j["board"]["square_px"];
  expect_manifest_rejected(j, "board.marker_px");
}

}  // namespace
}  // namespace lfd::calib
