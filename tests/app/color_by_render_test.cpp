// --color-by in headless images: the quantity's colours replace the material's, and the legend
// shows at the bottom right, with or without --ui; contacts paint what touches a collider.
#include <gtest/gtest.h>

#include <string>

#include "cloth_pixels.h"
#include "io/png_image.h"
#include "run_wobble.h"

namespace {

using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

constexpr int image_width = 640, image_height = 400;

wobble::RgbaImage render(const TemporaryFolder& folder, const std::string& name,
                         const std::string& options) {
  const auto run = run_wobble("cloth --headless --frames 30 --width 640 --height 400 " + options +
                                  " --screenshot '" + folder.file(name) + "'",
                              "DISPLAY= WAYLAND_DISPLAY=");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return wobble::read_png(folder.file(name));
}

long count_pixels(const wobble::RgbaImage& image, bool (*test)(const unsigned char*)) {
  long count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x)
      count += test(image.pixel(x, y)) ? 1 : 0;
  }
  return count;
}

// Pixels that differ between two images, in the box [x0, x1) × [y0, y1).
long differences(const wobble::RgbaImage& a, const wobble::RgbaImage& b, int x0, int y0, int x1,
                 int y1) {
  long count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const unsigned char *p = a.pixel(x, y), *q = b.pixel(x, y);
      count += (p[0] != q[0] || p[1] != q[1] || p[2] != q[2]) ? 1 : 0;
    }
  }
  return count;
}

TEST(ColorByRender, StrainReplacesTheMaterialAndTheLegendSitsAtTheBottomRight) {
  TemporaryFolder folder;
  const wobble::RgbaImage material = render(folder, "material.png", "");
  const wobble::RgbaImage strain = render(folder, "strain.png", "--color-by strain");
  ASSERT_EQ(strain.width, image_width);
  // The orange front is gone: the cloth is near-white, pink and red.
  const long orange = count_pixels(material, wobble::testing::is_cloth_front);
  EXPECT_GT(orange, 5000);
  EXPECT_LT(count_pixels(strain, wobble::testing::is_cloth_front), orange / 10);
  // The legend changes the bottom-right corner, and nothing changes where there is neither cloth
  // nor legend: the top of the picture and its bottom left.
  EXPECT_GT(differences(material, strain, image_width - 200, image_height - 60, image_width,
                        image_height),
            8000);
  EXPECT_EQ(differences(material, strain, 0, 0, image_width, 60), 0);
  EXPECT_EQ(differences(material, strain, 0, image_height - 100, image_width / 2, image_height), 0);
}

// The jelly coloured by volume change while its top is pushed in: where the drag squashes it the
// block shows the diverging map's blue, which neither its green material nor the neutral colour
// has (counted above the legend, whose own scale holds blue).
TEST(ColorByRender, VolumeShowsASquashedJellyBlue) {
  TemporaryFolder folder;
  const auto jelly = [&](const std::string& name, const std::string& options) {
    const std::string image = folder.file(name);
    const auto run = run_wobble(
        "jelly --headless --frames 30 --width 640 --height 400 "
        "--drag 688:0,-0.25,0@5-35 " +
            options + " --screenshot '" + image + "'",
        "DISPLAY= WAYLAND_DISPLAY=");
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return wobble::read_png(image);
  };
  const auto blue_above_legend = [](const wobble::RgbaImage& image) {
    long count = 0;
    for (int y = 0; y < image.height - 110; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const unsigned char* p = image.pixel(x, y);
        count += p[2] > p[0] + 60 && p[2] > p[1] + 30;
      }
    }
    return count;
  };
  const long in_material = blue_above_legend(jelly("material.png", ""));
  const long in_volume = blue_above_legend(jelly("volume.png", "--color-by volume"));
  EXPECT_GT(in_volume, in_material + 300) << in_volume << " blue pixels against " << in_material;
}

TEST(ColorByRender, SpeedAndStrainDifferAndThePanelKeepsTheLegend) {
  TemporaryFolder folder;
  const wobble::RgbaImage material = render(folder, "material.png", "");
  const wobble::RgbaImage strain = render(folder, "strain.png", "--color-by strain");
  const wobble::RgbaImage speed = render(folder, "speed.png", "--color-by speed");
  const wobble::RgbaImage speed_ui = render(folder, "speed_ui.png", "--color-by speed --ui");
  EXPECT_GT(differences(strain, speed, 0, 0, image_width, image_height), 5000);
  // The panel is at the top left; the legend at the bottom right stays with it. The cloth is
  // framed beside the panel then, so the ground grid seen through the legend's translucent
  // background moves: the corner is close to the one without the panel, not equal, and far
  // from one without a legend.
  const long legend =
      differences(material, speed, image_width - 200, image_height - 60, image_width, image_height);
  EXPECT_GT(legend, 8000);
  EXPECT_LT(
      differences(speed, speed_ui, image_width - 200, image_height - 60, image_width, image_height),
      legend / 2);
  EXPECT_GT(differences(speed, speed_ui, 0, 0, 300, 200), 20000);
}

// Strongly blue: the collider contact colour, not the drape's lit blue back (red over 0.6 of
// blue in sRGB) nor the grey-blue background and grid.
bool is_contact_blue(const unsigned char* rgb) {
  return rgb[2] > 120 && rgb[0] < 0.45 * rgb[2];
}

TEST(ColorByRender, ContactsPaintTheClothWhereItLiesOnTheBall) {
  TemporaryFolder folder;
  const auto drape = [&](const std::string& name, const std::string& options) {
    const auto run = run_wobble("'" + std::string(WOBBLE_ASSETS_DIR) +
                                    "/drape.json' --headless --frames 120 --width 640 "
                                    "--height 400 " +
                                    options + " --screenshot '" + folder.file(name) + "'",
                                "DISPLAY= WAYLAND_DISPLAY=");
    EXPECT_EQ(run.exit_code, 0) << run.err;
    wobble::RgbaImage image = wobble::read_png(folder.file(name));
    // The legend's blue block is not the cloth: only the picture above it counts.
    image.height = image_height - 100;
    return image;
  };
  const wobble::RgbaImage material = drape("material.png", "");
  const wobble::RgbaImage contacts = drape("contacts.png", "--color-by contacts");
  const long blue = count_pixels(contacts, is_contact_blue);
  // The vertices the solve holds against the ball (about a hundred of the 1,600 on the ball's
  // cap; between them the taut cloth spans a hair above it).
  EXPECT_GT(blue, 500) << "the cloth on top of the ball";
  EXPECT_LT(count_pixels(material, is_contact_blue), blue / 10);
  // The orange front is gone: what is not in contact is grey.
  EXPECT_LT(count_pixels(contacts, wobble::testing::is_cloth_front),
            count_pixels(material, wobble::testing::is_cloth_front) / 10);
}

}  // namespace
