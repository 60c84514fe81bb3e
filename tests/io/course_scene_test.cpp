#include "io/course_scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/png_image.h"
#include "sim/input_error.h"
#include "temporary_folder.h"

namespace {

// A quad (0,0,0) (2,0,0) (2,1,0) (0,2,0) with uv, plus a triangle on the far side, in a
// subfolder so that relative paths are exercised.
const char* const quad_obj =
    "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 2 0\nv 4 0 0\n"
    "vt 0 0\nvt 1 0\nvt 1 0.5\nvt 0 1\n"
    "f 1/1 2/2 3/3 4/4\nf 2 5 3\n";

class CourseScene : public ::testing::Test {
 protected:
  CourseScene() {
    std::filesystem::create_directories(folder_.path() / "meshes");
    write("meshes/sheet.obj", quad_obj);
    write("meshes/chain.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nl 1 2 3\n");
    wobble::RgbaImage image;
    image.width = image.height = 2;
    image.pixels.assign(16, 200);
    wobble::write_png(folder_.file("check.png"), image);
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(folder_.file(name), std::ios::binary) << text;
  }
  std::string json_path() const { return folder_.file("sheet.json"); }
  // The one-line message for loading `text` as sheet.json, or "" when it loads.
  std::string error(const std::string& text) {
    write("sheet.json", text);
    try {
      wobble::load_course_scene(json_path());
    } catch (const wobble::InputError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      return e.what();
    }
    return "";
  }
  // The message starts with the JSON file and the key, and says `what`.
  void expect_key_error(const std::string& text, const std::string& key, const std::string& what) {
    const std::string message = error(text);
    SCOPED_TRACE(text);
    EXPECT_EQ(message.rfind(json_path() + ": key `" + key + "`: ", 0), 0u) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }

  wobble::testing::TemporaryFolder folder_;
};

TEST(IsCourseScene, NeedsAnObjectWithObjAndB) {
  EXPECT_TRUE(wobble::is_course_scene(nlohmann::json::parse(R"({"obj": "a.obj", "b": []})")));
  EXPECT_FALSE(wobble::is_course_scene(nlohmann::json::parse(R"({"obj": "a.obj"})")));
  EXPECT_FALSE(wobble::is_course_scene(nlohmann::json::parse(R"({"b": [1], "k": 1})")));
  EXPECT_FALSE(wobble::is_course_scene(nlohmann::json::parse(R"(["obj", "b"])")));
}

TEST_F(CourseScene, FollowsTheReferenceProgramsRules) {
  write("sheet.json",
        R"({"obj": "meshes/sheet.obj", "b": [4, 1], "k": 250.5, "png": "check.png"})");
  const wobble::Scene scene = wobble::load_course_scene(json_path());
  EXPECT_EQ(scene.name, "sheet");
  EXPECT_EQ(scene.description, "course scene: 5 vertices, 8 springs");
  const wobble::SpringNetwork& net = scene.network;
  ASSERT_EQ(net.V.rows(), 5);
  EXPECT_EQ(net.V.row(3), Eigen::RowVector3d(0, 2, 0));
  // The quad's 6 pairs and the triangle's 3, of which 1–2 (0-based) is shared: 8, sorted.
  Eigen::MatrixXi E(8, 2);
  E << 0, 1, 0, 2, 0, 3, 1, 2, 1, 3, 1, 4, 2, 3, 2, 4;
  EXPECT_EQ(net.E, E);
  Eigen::MatrixXi F(3, 3);
  F << 0, 1, 2, 0, 2, 3, 1, 4, 2;
  EXPECT_EQ(net.F, F);
  // By hand: triangle 0 1 2 is right-angled at 1 (area 1): 0.25, 0.5, 0.25. Triangle 0 2 3 is
  // acute (area 2, cot 0.5, 0.75, 0.5 at 0, 2, 3): 0.6875, 0.625, 0.6875. Triangle 1 4 2 is
  // right-angled at 1 (area 1): 0.5, 0.25, 0.25.
  Eigen::VectorXd m(5);
  m << 0.25 + 0.6875, 0.5 + 0.5, 0.25 + 0.625 + 0.25, 0.6875, 0.25;
  EXPECT_LE((net.m - m).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(scene.pins, (std::vector<int>{3, 0}));
  EXPECT_EQ(scene.params.k, 250.5);
  EXPECT_EQ(scene.params.dt, 1.0 / 30.0);
  EXPECT_EQ(scene.params.iterations, 50);
  EXPECT_EQ(scene.params.gravity, Eigen::Vector3d(0, -9.8, 0));
  EXPECT_EQ(scene.params.gravity_model, wobble::GravityModel::force_per_vertex);
  EXPECT_EQ(scene.initial_velocity.size(), 0) << "starts at rest";
  EXPECT_TRUE(std::filesystem::equivalent(scene.look.texture, folder_.file("check.png")));
  ASSERT_EQ(scene.look.uv.rows(), 5);
  EXPECT_EQ(scene.look.uv.row(2), Eigen::RowVector2d(1, 0.5));
  EXPECT_EQ(scene.look.uv.row(4), Eigen::RowVector2d(0, 0)) << "no vt given";
  EXPECT_TRUE(scene.notes.empty());
}

TEST_F(CourseScene, ConstantMassReplacesAreas) {
  write("sheet.json", R"({"obj": "meshes/chain.obj", "b": [], "k": 10, "m": 0.125})");
  const wobble::Scene scene = wobble::load_course_scene(json_path());
  EXPECT_EQ(scene.network.m, Eigen::VectorXd::Constant(3, 0.125));
  EXPECT_EQ(scene.network.E.rows(), 2);
  EXPECT_EQ(scene.network.F.rows(), 0) << "a spring network has nothing to draw but springs";
  EXPECT_TRUE(scene.pins.empty());
  EXPECT_EQ(scene.look.uv.size(), 0);
  EXPECT_TRUE(scene.look.texture.empty());
}

TEST_F(CourseScene, TextureWithoutUvIsNoted) {
  write("sheet.json",
        R"({"obj": "meshes/chain.obj", "b": [1], "k": 10, "m": 1, "png": "check.png"})");
  EXPECT_EQ(wobble::load_course_scene(json_path()).notes.size(), 1u);
}

TEST_F(CourseScene, LoadsFromAnAlreadyParsedObject) {
  const auto object = nlohmann::json::parse(R"({"obj": "meshes/chain.obj", "b": [2], "k": 3,
                                                "m": 2})");
  const wobble::Scene scene = wobble::load_course_scene(folder_.file("given.json"), object);
  EXPECT_EQ(scene.name, "given");
  EXPECT_EQ(scene.pins, (std::vector<int>{1}));
}

TEST_F(CourseScene, RefusesWhatTheCourseDoesNotDefine) {
  expect_key_error(R"({"obj": "meshes/sheet.obj", "b": [1], "k": 1, "bc": [[1, 0, 0, 0]]})", "bc",
                   "not supported");
  // A spring network has no triangles, so no Voronoi areas to be masses.
  expect_key_error(R"({"obj": "meshes/chain.obj", "b": [1], "k": 1})", "m",
                   "vertex 1 is in no triangle");
}

TEST_F(CourseScene, RefusesBadKeys) {
  const std::string obj = R"("obj": "meshes/sheet.obj")";
  expect_key_error("{" + obj + R"(, "b": [1]})", "k", "missing");
  expect_key_error("{" + obj + R"(, "b": [1], "k": 0})", "k", "got 0, expected a positive");
  expect_key_error("{" + obj + R"(, "b": [1], "k": -5.5})", "k", "got -5.5");
  expect_key_error("{" + obj + R"(, "b": [1], "k": "10"})", "k", R"(got "10")");
  expect_key_error("{" + obj + R"(, "b": [1], "k": true})", "k", "got true");
  expect_key_error("{" + obj + R"(, "b": [1], "k": 1, "m": 0})", "m", "got 0, expected a positive");
  expect_key_error("{" + obj + R"(, "b": [1], "k": 1, "m": [1]})", "m", "got [1]");
  expect_key_error("{" + obj + R"(, "b": 1, "k": 1})", "b", "got 1, expected a list");
  expect_key_error("{" + obj + R"(, "b": [1, 0], "k": 1})", "b",
                   "entry 1 is 0, expected a 1-based");
  expect_key_error("{" + obj + R"(, "b": [6], "k": 1})", "b",
                   "entry 0 is 6, expected a 1-based vertex index 1 to 5");
  expect_key_error("{" + obj + R"(, "b": [-1], "k": 1})", "b", "entry 0 is -1");
  expect_key_error("{" + obj + R"(, "b": [18446744073709551615], "k": 1})", "b", "1 to 5");
  expect_key_error("{" + obj + R"(, "b": [1.5], "k": 1})", "b",
                   "entry 0 is 1.5, expected an integer");
  expect_key_error("{" + obj + R"(, "b": ["2"], "k": 1})", "b", "expected an integer");
  expect_key_error("{" + obj + R"(, "b": [2, 3, 2], "k": 1})", "b",
                   "entry 2 is 2, a vertex already");
  expect_key_error(R"({"obj": 7, "b": [1], "k": 1})", "obj", "got 7, expected an OBJ mesh path");
  expect_key_error(R"({"obj": "meshes/none.obj", "b": [1], "k": 1})", "obj",
                   "'" + folder_.file("meshes/none.obj") + "': no such file, expected an OBJ mesh");
  expect_key_error("{" + obj + R"(, "b": [1], "k": 1, "png": "none.png"})", "png",
                   "'" + folder_.file("none.png") + "': no such file, expected a PNG texture");
  // What is not a regular file, and a texture that is not an image, are refused when the scene
  // loads, drawn or not.
  expect_key_error(R"({"obj": "meshes", "b": [1], "k": 1})", "obj",
                   "'" + folder_.file("meshes") + "': is a folder, expected an OBJ mesh");
  expect_key_error("{" + obj + R"(, "b": [1], "k": 1, "png": "meshes"})", "png",
                   "is a folder, expected a PNG texture");
  expect_key_error("{" + obj + R"(, "b": [1], "k": 1, "png": "meshes/sheet.obj"})", "png",
                   "sheet.obj': is not a readable image");
}

// Only the course's own keys: anything else (a typo, or a key of Wobble's own format) stops
// loading, naming the file and the key.
TEST_F(CourseScene, RefusesKeysTheCourseDoesNotHave) {
  const std::string obj = R"("obj": "meshes/sheet.obj", "b": [1], "k": 1)";
  const std::string takes = "unknown key, a course scene takes only obj, b, k, m and png";
  for (const std::string key : {"colliders", "self_collision", "mass", "comment", "B", "p ng"}) {
    expect_key_error("{" + obj + ", \"" + key + "\": 1}", key, takes);
  }
  // A key that appears twice is refused while the file is parsed, before any key is looked at.
  const std::string message = error("{" + obj + R"(, "k": 2})");
  EXPECT_EQ(message, json_path() + R"(: line 1: key "k" appears twice in the same object)");
}

// `b` takes a whole number in any spelling JSON has for it, and nothing that is not whole.
TEST_F(CourseScene, PinsAreWholeNumbersHoweverSpelt) {
  write("sheet.json", R"({"obj": "meshes/sheet.obj", "b": [4.0, 1e0, 20e-1, 0.3e1], "k": 1})");
  const wobble::Scene scene = wobble::load_course_scene(json_path());
  EXPECT_EQ(scene.pins, std::vector<int>({3, 0, 1, 2}));
  const std::string obj = R"("obj": "meshes/sheet.obj", "k": 1)";
  expect_key_error("{" + obj + R"(, "b": [1.000001]})", "b",
                   "entry 0 is 1.000001, expected an integer");
  expect_key_error("{" + obj + R"(, "b": [6.0]})", "b",
                   "entry 0 is 6.0, expected a 1-based vertex index 1 to 5");
  expect_key_error("{" + obj + R"(, "b": [0e3]})", "b", "expected a 1-based vertex index 1 to 5");
  expect_key_error("{" + obj + R"(, "b": [1e300]})", "b", "expected a 1-based vertex index 1 to 5");
  expect_key_error("{" + obj + R"(, "b": [4, 4.0]})", "b",
                   "entry 1 is 4.0, a vertex already pinned");
}

// The course's k and m keep to the limits of --k and of Wobble's own scenes (sim/value_limits.h).
TEST_F(CourseScene, ValuesKeepToTheSharedLimits) {
  const std::string obj = R"("obj": "meshes/sheet.obj")";
  expect_key_error("{" + obj + R"(, "b": [1], "k": 1e308})", "k",
                   "got 1e+308, expected a positive number within the limits 1e-6 to 1e8 N/m");
  expect_key_error("{" + obj + R"(, "b": [1], "k": 1, "m": 1e-300})", "m",
                   "got 1e-300, expected a positive number within the limits 1e-9 to 1e6 kg");
  expect_key_error("{" + obj + R"(, "b": [1], "k": 1, "m": 1e300})", "m", "1e6 kg");
  // Without m, areas so small that the masses underflow name m, not a vertex.
  write("meshes/tiny.obj", "v 0 0 0\nv 1e-6 0 0\nv 0 1e-6 0\nf 1 2 3\n");
  expect_key_error(R"({"obj": "meshes/tiny.obj", "b": [1], "k": 1})", "m",
                   "missing, and the OBJ's Voronoi areas give masses from 1.25e-13 to 2.5e-13 kg, "
                   "expected each within the limits 1e-9 to 1e6 kg");
  // The limits themselves load.
  EXPECT_EQ(error("{" + obj + R"(, "b": [1], "k": 1e8, "m": 1e6})"), "");
}

TEST_F(CourseScene, MalformedJsonNamesItsLine) {
  const std::string message = error("{\n  \"obj\": \"meshes/sheet.obj\",\n  \"b\": [1,, 2],\n}\n");
  EXPECT_EQ(message.rfind(json_path() + ": line 3: malformed JSON: ", 0), 0u) << message;
  EXPECT_EQ(error(""), json_path() + ": the file is empty, expected a JSON object");
  EXPECT_EQ(error(" \n\t\n"), json_path() + ": the file is empty, expected a JSON object");
  EXPECT_EQ(error("{\n"), json_path() + ": line 2: malformed JSON: " +
                              "syntax error while parsing object key - unexpected end of input; "
                              "expected string literal");
}

TEST_F(CourseScene, OtherFilesAreNamed) {
  EXPECT_EQ(error(R"({"obj": "meshes/sheet.obj", "k": 1})"),
            json_path() + ": not a course scene, expected a JSON object with keys `obj` and `b`");
  write("meshes/bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  EXPECT_EQ(error(R"({"obj": "meshes/bad.obj", "b": [1], "k": 1, "m": 1})")
                .rfind(folder_.file("meshes/bad.obj") + ": line 3: ", 0),
            0u);
  try {
    wobble::load_course_scene(folder_.file("absent.json"));
    FAIL() << "expected InputError";
  } catch (const wobble::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              folder_.file("absent.json") + ": no such file, expected a scene (JSON)");
  }
}

}  // namespace
