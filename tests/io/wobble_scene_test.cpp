#include "io/wobble_scene.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <fstream>

#include "io/load_scene.h"
#include "sim/input_error.h"
#include "sim/shapes/builtin_scenes.h"
#include "temporary_folder.h"

namespace {

using wobble::testing::TemporaryFolder;

// Write `json` as FOLDER/scene.json and load it.
wobble::Scene load(const TemporaryFolder& folder, const std::string& json) {
  std::ofstream(folder.file("scene.json")) << json;
  return wobble::load_scene(folder.file("scene.json"));
}

// The InputError message that loading `json` gives.
std::string scene_error(const std::string& json) {
  TemporaryFolder folder;
  try {
    load(folder, json);
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(WobbleScene, ClothGeneratorMatchesTheBuiltInCloth) {
  TemporaryFolder folder;
  const wobble::Scene scene = load(folder, R"({
    "mesh": {"generator": "cloth", "resolution": 40, "size": 1.0, "height": 1.2},
    "pins": "top-corners",
    "material": {"k": 400, "density": 0.25}
  })");
  const wobble::Scene builtin = wobble::make_builtin_scene("cloth");
  EXPECT_TRUE(scene.network.V.isApprox(builtin.network.V));
  EXPECT_EQ(scene.network.E, builtin.network.E);
  EXPECT_EQ(scene.network.F, builtin.network.F);
  EXPECT_TRUE(scene.network.m.isApprox(builtin.network.m, 1e-12));
  EXPECT_EQ(scene.pins, builtin.pins);
  EXPECT_EQ(scene.params.k, builtin.params.k);
  EXPECT_EQ(scene.name, "scene");  // no "name": the file's stem
  EXPECT_TRUE(scene.notes.empty());
}

// simulation.solver names the step solver; without it, the default (the course's local-global).
TEST(WobbleScene, ReadsTheSolver) {
  TemporaryFolder folder;
  const wobble::Scene lbfgs = load(folder, R"({
    "mesh": {"generator": "cloth", "resolution": 8},
    "simulation": {"solver": "lbfgs", "iterations": 12}
  })");
  EXPECT_EQ(lbfgs.params.solver, "lbfgs");
  EXPECT_EQ(lbfgs.params.iterations, 12);
  const wobble::Scene plain = load(folder, R"({"mesh": {"generator": "cloth", "resolution": 8},
                                               "simulation": {"dt": 0.01}})");
  EXPECT_EQ(plain.params.solver, "local-global");
  const wobble::Scene named = load(folder, R"({"mesh": {"generator": "cloth", "resolution": 8},
                       "simulation": {"solver": "local-global", "chebyshev": true}})");
  EXPECT_EQ(named.params.solver, "local-global");
  EXPECT_TRUE(named.params.chebyshev);
}

TEST(WobbleScene, JellyGeneratorMatchesTheBuiltInJelly) {
  TemporaryFolder folder;
  const wobble::Scene scene = load(folder, R"({
    "name": "j", "mesh": {"generator": "jelly"}, "pins": "bottom",
    "initial_velocity": {"sway": 2.0}
  })");
  const wobble::Scene builtin = wobble::make_builtin_scene("jelly");
  EXPECT_TRUE(scene.network.V.isApprox(builtin.network.V));
  EXPECT_TRUE(scene.network.m.isApprox(builtin.network.m, 1e-12));
  EXPECT_EQ(scene.pins, builtin.pins);
  EXPECT_TRUE(scene.initial_velocity.isApprox(builtin.initial_velocity));
  EXPECT_EQ(scene.params.k, 1500.0);
}

TEST(WobbleScene, VerticalClothHasItsTopEdgeAtTheHeightFacingPlusZ) {
  TemporaryFolder folder;
  const wobble::Scene scene = load(folder, R"({
    "mesh": {"generator": "cloth", "resolution": 5, "size": 2.0, "orientation": "vertical",
             "height": 3.0, "springs": ["structural"]},
    "pins": ["top-edge", 24], "material": {"mass": 2.0},
    "simulation": {"dt": 0.01, "iterations": 7, "gravity": 5}
  })");
  const Eigen::MatrixXd& V = scene.network.V;
  EXPECT_DOUBLE_EQ(V.col(1).maxCoeff(), 3.0);
  EXPECT_DOUBLE_EQ(V.col(1).minCoeff(), 1.0);
  EXPECT_DOUBLE_EQ(V.col(2).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(scene.pins, (std::vector<int>{0, 1, 2, 3, 4, 24}));
  EXPECT_EQ(scene.network.E.rows(), 2 * 5 * 4);  // structural only
  EXPECT_NEAR(scene.network.m.sum(), 2.0, 1e-12);
  EXPECT_EQ(scene.params.dt, 0.01);
  EXPECT_EQ(scene.params.iterations, 7);
  EXPECT_TRUE(scene.params.gravity.isApprox(Eigen::Vector3d(0, -5, 0)));
  // Faces turn to +z: the first triangle's normal.
  const Eigen::RowVector3d a = V.row(scene.network.F(0, 0)), b = V.row(scene.network.F(0, 1)),
                           c = V.row(scene.network.F(0, 2));
  EXPECT_GT((b - a).cross(c - a).z(), 0.0);
  // Texture coordinates: v = 1 along the top edge.
  ASSERT_EQ(scene.look.uv.rows(), 25);
  EXPECT_EQ(scene.look.uv(0, 1), 1.0);
  EXPECT_EQ(scene.look.uv(24, 0), 1.0);
}

TEST(WobbleScene, CameraAndColours) {
  TemporaryFolder folder;
  const wobble::Scene scene = load(folder, R"({
    "mesh": {"generator": "cloth", "resolution": 3},
    "camera": {"position": [0, 1, 5], "target": [0, 1, 0]},
    "appearance": {"front_color": [1, 0, 0], "back_color": [0, 0, 1]}
  })");
  EXPECT_TRUE(scene.look.camera_position->isApprox(Eigen::Vector3d(0, 1, 5)));
  EXPECT_TRUE(scene.look.front_color->isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(scene.notes.empty());
  EXPECT_TRUE(scene.pins.empty());  // none asked for, none given
}

// One rule at every level: a key the scene format does not have stops loading, with one line
// naming the file, the key's path and the keys that object takes. (They were a note before, and
// a misspelt key ran with its default.)
TEST(WobbleScene, UnknownKeysAreRefusedAtEveryLevel) {
  const std::string cloth = R"("mesh": {"generator": "cloth", "resolution": 3})";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{" + cloth + R"(, "wind": 3})",
       "scene.json: wind: unknown key, a Wobble scene takes name, "
       "description, mesh, material, simulation, colliders"},
      {R"({"mesh": {"generator": "cloth", "colour": 1}})",
       "scene.json: mesh.colour: unknown key, a cloth generator's mesh takes generator, "
       "resolution, size, springs, orientation, height, offset"},
      {R"({"mesh": {"generator": "jelly", "height": 1}})",
       "scene.json: mesh.height: unknown key, a jelly generator's mesh takes generator, "
       "resolution, size, offset"},
      {R"({"mesh": {"generator": "cloth", "file": "a.obj"}})",
       "scene.json: mesh.file: unknown key, a cloth generator's mesh takes"},
      {"{" + cloth + R"(, "material": {"k": 10, "densty": 2}})",
       "scene.json: material.densty: unknown key, material takes k, friction, density, mass, "
       "vertex_masses"},
      {"{" + cloth + R"(, "simulation": {"iteratons": 10}})",
       "scene.json: simulation.iteratons: unknown key, simulation takes dt, iterations"},
      {"{" + cloth + R"(, "simulation": {"wind": {"velocity": [1, 0, 0], "gust": 1}}})",
       "scene.json: simulation.wind.gust: unknown key, simulation.wind takes model, velocity"},
      {"{" + cloth + R"(, "camera": {"position": [0, 0, 1], "target": [0, 0, 0], "fov": 40}})",
       "scene.json: camera.fov: unknown key, camera takes position, target"},
      {"{" + cloth + R"(, "appearance": {"colour": [1, 0, 0]}})",
       "scene.json: appearance.colour: unknown key, appearance takes front_color, back_color, "
       "texture"},
      {"{" + cloth + R"(, "initial_velocity": {"sway": 1, "swing": 2}})",
       "scene.json: initial_velocity.swing: unknown key, initial_velocity (an object) takes sway"},
      // A course scene's keys in a Wobble scene are unknown too.
      {"{" + cloth + R"(, "k": 400})", "scene.json: k: unknown key, a Wobble scene takes"},
      // Refused before anything is built or read: the mesh file named here does not exist.
      {R"({"mesh": {"file": "none.obj"}, "Pins": "top"})", "scene.json: Pins: unknown key"},
  };
  for (const auto& [json, expected] : cases) {
    const std::string message = scene_error(json);
    EXPECT_NE(message.find(expected), std::string::npos) << json << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// A whole-number field takes any JSON spelling of a whole number (10, 10.0, 1e1, 100e-1), and
// still refuses a fraction or a number out of range.
TEST(WobbleScene, WholeNumbersInAnySpelling) {
  TemporaryFolder folder;
  const wobble::Scene scene = load(folder, R"({
    "mesh": {"generator": "cloth", "resolution": 1e1},
    "simulation": {"iterations": 50.0},
    "pins": [2E0, 90e-1, 0.0]
  })");
  EXPECT_EQ(scene.network.V.rows(), 100);
  EXPECT_EQ(scene.params.iterations, 50);
  EXPECT_EQ(scene.pins, std::vector<int>({0, 2, 9}));
  const wobble::Scene jelly =
      load(folder, R"({"mesh": {"generator": "jelly", "resolution": 20e-1}})");
  EXPECT_EQ(jelly.network.V.rows(), 27);

  const std::vector<std::pair<std::string, std::string>> refused = {
      {R"({"mesh": {"generator": "cloth", "resolution": 10.5}})",
       "mesh.resolution: expected a whole number from 2 to 256, got 10.5"},
      {R"({"mesh": {"generator": "cloth", "resolution": 2.57e2}})",
       "mesh.resolution: expected a whole number from 2 to 256, got 257.0"},
      {R"({"mesh": {"generator": "cloth"}, "simulation": {"iterations": 1e300}})",
       "simulation.iterations: expected a whole number from 1 to 5000, got 1e+300"},
      {R"({"mesh": {"generator": "cloth"}, "simulation": {"iterations": 1e-1}})",
       "simulation.iterations: expected a whole number from 1 to 5000, got 0.1"},
      {R"({"mesh": {"generator": "cloth"}, "simulation": {"iterations": -0.0}})",
       "simulation.iterations: expected a whole number from 1 to 5000, got -0.0"},
      {R"({"mesh": {"generator": "cloth"}, "simulation": {"iterations": 18446744073709551616}})",
       "simulation.iterations: expected a whole number from 1 to 5000"},
      {R"({"mesh": {"generator": "cloth"}, "pins": [3.25]})",
       "pins: vertex index 3.25 is not a whole number (expected 0 to 1599)"},
  };
  for (const auto& [json, expected] : refused) {
    const std::string message = scene_error(json);
    EXPECT_NE(message.find("scene.json: " + expected), std::string::npos)
        << json << " -> " << message;
  }
}

// Every value a scene sets keeps to the command line's limits (sim/value_limits.h), and the
// message names the key, also where only what two keys give together is out of range.
TEST(WobbleScene, ValuesKeepToTheSharedLimits) {
  const std::string cloth = R"("mesh": {"generator": "cloth", "resolution": 4})";
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{" + cloth + R"(, "material": {"k": 1e308}})",
       "material.k: expected a positive number within the limits 1e-6 to 1e8 N/m, got 1e+308"},
      {"{" + cloth + R"(, "simulation": {"dt": 1e300}})",
       "simulation.dt: expected a positive number within the limits 1e-9 to 1 s"},
      {"{" + cloth + R"(, "simulation": {"gravity": [0, -1e300, 0]}})",
       "simulation.gravity: expected three numbers [x, y, z], each within the limits -1000 to "
       "1000 m/s²"},
      {"{" + cloth + R"(, "simulation": {"gravity": 5000}})", "simulation.gravity"},
      {"{" + cloth + R"(, "initial_velocity": [1e200, 0, 0]})", "initial_velocity: expected"},
      {"{" + cloth + R"(, "initial_velocity": {"sway": 1e9}})", "initial_velocity.sway"},
      {"{" + cloth + R"(, "material": {"density": 1e300}})", "material.density"},
      {"{" + cloth + R"(, "material": {"mass": 1e-300}})", "material.mass: expected"},
      {"{" + cloth + R"(, "camera": {"position": [0, 0, 1e300], "target": [0, 0, 0]}})",
       "camera.position"},
      {R"({"mesh": {"generator": "cloth", "size": 1e-30}})", "mesh.size"},
      {R"({"mesh": {"generator": "jelly", "resolution": 25}})", "mesh.resolution"},
      // Each value within its limits, but the masses they give together are not.
      {R"({"mesh": {"generator": "cloth", "resolution": 100}, "material": {"mass": 1e-6}})",
       "material.mass and mesh.resolution: vertex masses from 2.55e-11 to 1.02e-10 kg"},
      {R"({"mesh": {"file": "tri.obj", "scale": 1e-6}})",
       "mesh.scale: vertex masses from 3.12e-14 to 6.25e-14 kg, expected each within the "
       "limits 1e-9 to 1e6 kg"},
      {R"({"mesh": {"file": "tri.obj", "scale": 1e-300}})",
       "mesh.scale: expected a positive number within the limits 1e-6 to 1e6"},
      {R"({"mesh": {"file": "tri.obj", "offset": [0, 1e6, 0]}})",
       "mesh.offset: vertex coordinates from 0 to 1000001 m"},
  };
  for (const auto& [json, expected] : cases) {
    TemporaryFolder folder;
    std::ofstream(folder.file("tri.obj")) << obj;
    std::string message = "(no error)";
    try {
      load(folder, json);
    } catch (const wobble::InputError& error) {
      message = error.what();
    }
    EXPECT_NE(message.find("scene.json: "), std::string::npos) << json << " -> " << message;
    EXPECT_NE(message.find(expected), std::string::npos) << json << " -> " << message;
  }
}

TEST(WobbleScene, ErrorsNameTheFileTheKeyAndWhatWasExpected) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"mesh": {"generator": "torus"}})", "mesh.generator: expected \"cloth\" or \"jelly\""},
      {R"({"mesh": {}})", "mesh: expected a \"generator\" or a \"file\""},
      {R"({"mesh": {"generator": "cloth"}, "material": {"k": -3}})",
       "material.k: expected a positive number within the limits 1e-6 to 1e8 N/m, got -3"},
      {R"({"mesh": {"generator": "cloth"}, "material": {"k": "stiff"}})",
       "material.k: expected a positive number within the limits 1e-6 to 1e8 N/m, got \"stiff\""},
      {R"({"mesh": {"generator": "cloth"}, "material": {"density": 1, "mass": 1}})",
       "expected either density or mass"},
      {R"({"mesh": {"generator": "cloth"}, "simulation": {"dt": 0}})", "simulation.dt"},
      {R"({"mesh": {"generator": "cloth", "resolution": 1}})", "mesh.resolution"},
      {R"({"mesh": {"generator": "jelly"}, "pins": "top-edge"})", "only on the cloth generator"},
      {R"({"mesh": {"generator": "cloth", "resolution": 3}, "pins": [9]})",
       "vertex index 9 is out of range (0 to 8)"},
      {R"({"mesh": {"generator": "cloth"}, "pins": [1.5]})",
       "pins: vertex index 1.5 is not a whole number (expected 0 to 1599)"},
      {R"({"mesh": {"generator": "cloth"}, "pins": [1e4]})",
       "pins: vertex index 10000.0 is out of range (0 to 1599)"},
      {R"({"mesh": {"file": "missing.obj"}})", "missing.obj"},
      {R"({"mesh": {"generator": "cloth"}, "appearance": {"texture": "none.png"}})",
       "none.png': no such file, expected a PNG texture"},
      // Textures are checked when the scene loads, drawn or not; paths that cannot be resolved
      // name the key.
      {R"({"mesh": {"generator": "cloth"}, "appearance": {"texture": "scene.json"}})",
       "appearance.texture: '"},
      {R"({"mesh": {"generator": "cloth"}, "appearance": {"texture": "scene.json"}})",
       "scene.json': is not a readable image"},
      {R"({"mesh": {"generator": "cloth"}, "appearance": {"texture": "."}})",
       "is a folder, expected a PNG texture"},
      {R"({"mesh": {"file": "scene.json/inside.obj"}})", "mesh.file: '"},
      {R"({"mesh": {"file": "scene.json/inside.obj"}})",
       "inside.obj': cannot be reached: a part of the path is not a folder"},
      {R"({"mesh": {"file": "scene.json"}})", "mesh.file: '"},
      {R"({"mesh": {"file": "scene.json"}})", "unknown mesh format"},
      {R"({"mesh": {"generator": "cloth"}, "appearance": {"front_color": [2, 0, 0]}})",
       "appearance.front_color: expected a colour"},
      {R"({"mesh": {"generator": "cloth"}, "camera": {"position": [0, 0, 1]}})",
       "camera.target: expected both a position and a target"},
      {R"({"mesh": {"generator": "cloth"},)", "line 1: malformed JSON"},
      {R"({"something": 1})", "not a scene"},
      // The keys a saved scene uses to state its network and settings exactly.
      {R"({"mesh": {"generator": "cloth", "resolution": 2}, "material": {"vertex_masses": [1]}})",
       "material.vertex_masses: expected a list of 4 masses, one for every vertex"},
      {R"({"mesh": {"generator": "cloth", "resolution": 2},
           "material": {"vertex_masses": [1, 1, 0, 1]}})",
       "material.vertex_masses[2]: expected a mass within the limits"},
      {R"({"mesh": {"generator": "cloth", "resolution": 2},
           "material": {"vertex_masses": [1, 1, 1, 1], "density": 2}})",
       "material.vertex_masses: expected either vertex_masses or a density or mass"},
      {R"({"mesh": {"generator": "cloth"}, "simulation": {"gravity_model": "heavy"}})",
       "simulation.gravity_model: expected \"acceleration\" or \"force_per_vertex\""},
      // The solver's names come from the registry, as gravity_model's values are listed.
      {R"({"mesh": {"generator": "cloth"}, "simulation": {"solver": "L-BFGS"}})",
       "simulation.solver: expected \"local-global\" or \"lbfgs\", got \"L-BFGS\""},
      {R"({"mesh": {"generator": "cloth"}, "simulation": {"solver": ["lbfgs"]}})",
       "simulation.solver: expected a string"},
      {R"({"mesh": {"generator": "cloth"}, "simulation": {"first_iterate": "zero"}})",
       "simulation.first_iterate: expected \"current_positions\" or \"inertial_prediction\""},
      {R"({"mesh": {"generator": "cloth"},
           "simulation": {"wind": {"velocity": [1, 0, 0], "model": "storm"}}})",
       "simulation.wind.model: expected \"aerodynamic\" or \"course\""},
      {R"({"mesh": {"file": ")" + std::string(WOBBLE_ASSETS_DIR) +
           R"(/meshes/jelly_cube.mesh", "polygon_springs": false}})",
       "mesh.polygon_springs: expected true (false applies to an unfilled .obj only)"},
      // A saved solid's tetrahedra: with the saved form of an OBJ only, each in range, none flat.
      {R"({"mesh": {"file": ")" + std::string(WOBBLE_ASSETS_DIR) +
           R"(/meshes/blob.obj", "tetrahedra": [[0, 1, 2, 3]]}})",
       "mesh.tetrahedra: expected to come with \"polygon_springs\": false"},
  };
  for (const auto& [json, expected] : cases) {
    const std::string message = scene_error(json);
    EXPECT_NE(message.find("scene.json"), std::string::npos) << json << " -> " << message;
    EXPECT_NE(message.find(expected), std::string::npos) << json << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// A saved solid's tetrahedra (mesh.tetrahedra, beside an OBJ of its springs): kept as written,
// and each refused by its index when out of range or flat.
TEST(WobbleScene, TetrahedraBesideASavedObj) {
  TemporaryFolder folder;
  std::ofstream(folder.file("solid.obj"))
      << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\n"
         "f 1 2\nf 1 3\nf 1 4\nf 2 3\nf 2 4\nf 3 4\nf 2 5\nf 3 5\nf 4 5\n";
  const auto scene_with = [](const std::string& tetrahedra) {
    return R"({"mesh": {"file": "solid.obj", "polygon_springs": false, "tetrahedra": )" +
           tetrahedra + "}}";
  };
  const wobble::Scene solid = load(folder, scene_with("[[0, 1, 2, 3], [1, 2, 3, 4]]"));
  ASSERT_EQ(solid.network.T.rows(), 2);
  EXPECT_EQ(solid.network.T(1, 3), 4);
  const std::pair<std::string, std::string> cases[] = {
      {"[[0, 1, 2, 5]]",
       "mesh.tetrahedra[0]: expected a list of [a, b, c, d]: four distinct "
       "vertex indices from 0 to 4, not flat"},
      {"[[0, 1, 2, 3], [1, 1, 2, 3]]", "mesh.tetrahedra[1]: expected"},
      {"[[0, 1, 2, -1]]", "mesh.tetrahedra[0]: expected"},
      {"3", "mesh.tetrahedra: expected"},
  };
  for (const auto& [tetrahedra, expected] : cases) {
    std::string message = "(no error)";
    try {
      load(folder, scene_with(tetrahedra));
    } catch (const wobble::InputError& error) {
      message = error.what();
    }
    EXPECT_NE(message.find("scene.json: " + expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  std::ofstream(folder.file("scene.json"))
      << R"({"mesh": {"file": "solid.obj", "tetrahedra": [[0, 1, 2, 3]]}})";
  EXPECT_THROW(wobble::load_scene(folder.file("scene.json")), wobble::InputError);
}

TEST(WobbleScene, MalformedJsonGivesTheLine) {
  const std::string message = scene_error("{\n  \"mesh\": {\"generator\": \"cloth\"},\n  oops\n}");
  EXPECT_NE(message.find("line 3: malformed JSON"), std::string::npos) << message;
}

// Found by fuzz_wobble_scene (ASan: stack-use-after-scope): with no "material", the masses were
// read through a JsonFields that referred to a temporary JSON object already destroyed.
TEST(WobbleScene, NoMaterialGivesTheDefaultDensity) {
  TemporaryFolder folder;
  // 0.25 kg/m² on a 2 m square; 200 kg/m³ in a 0.5 m cube.
  const wobble::Scene cloth =
      load(folder, R"({"mesh": {"generator": "cloth", "resolution": 3, "size": 2}})");
  EXPECT_NEAR(cloth.network.m.sum(), 1.0, 1e-12);  // sums of a few quarter cells
  const wobble::Scene jelly = load(folder, R"({"mesh": {"generator": "jelly", "resolution": 2}})");
  EXPECT_NEAR(jelly.network.m.sum(), 25.0, 1e-12);
}

// Found by fuzz_wobble_scene: load_wobble_scene on an object without "mesh" let nlohmann's
// out_of_range escape; load_scene checks first, but the function is public.
TEST(WobbleScene, LoadWobbleSceneRefusesWhatIsNotAWobbleScene) {
  for (const nlohmann::json& object :
       {nlohmann::json::parse(R"({"mdsh": {"file": "input.obj"}, "pins": "top"})"),
        nlohmann::json::parse("[1, 2]"), nlohmann::json(3.5)}) {
    try {
      wobble::load_wobble_scene("dir/scene.json", object);
      ADD_FAILURE() << object << " loaded";
    } catch (const wobble::InputError& error) {
      EXPECT_EQ(std::string(error.what()),
                "dir/scene.json: not a Wobble scene, expected a JSON object with a \"mesh\"");
    }
  }
}

// Found by fuzz_wobble_scene (nlohmann's assertion, kept on in the fuzz build): a pin band with
// neither "below" nor "above" looked up "above" in a const object that lacks it, which is
// undefined behaviour.
TEST(WobbleScene, PinBandWithoutBelowOrAboveIsRefused) {
  for (const std::string band : {R"({"ab1e308ove": 0.1})", R"({"below": 0.1, "above": 0.2})",
                                 R"({"below": -1})", R"({"above": "high"})"}) {
    const std::string message = scene_error(
        R"({"mesh": {"generator": "cloth", "resolution": 3}, "pins": [0, "top", )" + band + "]}");
    EXPECT_NE(message.find("scene.json: pins: expected a vertex index, \"top\""), std::string::npos)
        << band << " -> " << message;
  }
}

}  // namespace
