#ifndef WOBBLE_APP_CLI_COLOR_QUANTITY_H
#define WOBBLE_APP_CLI_COLOR_QUANTITY_H

#include <optional>
#include <string>

namespace wobble {

// What the surface and springs are coloured by, in the order the V key cycles through and the
// panel's combo lists them (PanelSettings::color_by is this as an int). A choice the command line
// (--color-by) and the viewer share; the colours themselves are app/viewer/quantity_colors.h's.
enum class ColorQuantity { material, strain, speed, contacts, volume };

inline ColorQuantity next_color_quantity(ColorQuantity quantity) {
  switch (quantity) {
    case ColorQuantity::material:
      return ColorQuantity::strain;
    case ColorQuantity::strain:
      return ColorQuantity::speed;
    case ColorQuantity::speed:
      return ColorQuantity::contacts;
    case ColorQuantity::contacts:
      return ColorQuantity::volume;
    case ColorQuantity::volume:
      return ColorQuantity::material;
  }
  return ColorQuantity::material;
}

// "material", "strain", "speed", "contacts", "volume".
inline const char* color_quantity_name(ColorQuantity quantity) {
  switch (quantity) {
    case ColorQuantity::material:
      return "material";
    case ColorQuantity::strain:
      return "strain";
    case ColorQuantity::speed:
      return "speed";
    case ColorQuantity::contacts:
      return "contacts";
    case ColorQuantity::volume:
      return "volume";
  }
  return "material";
}

// The quantity with that name, or nothing.
inline std::optional<ColorQuantity> color_quantity_named(const std::string& name) {
  for (ColorQuantity quantity :
       {ColorQuantity::material, ColorQuantity::strain, ColorQuantity::speed,
        ColorQuantity::contacts, ColorQuantity::volume}) {
    if (name == color_quantity_name(quantity)) return quantity;
  }
  return std::nullopt;
}

}  // namespace wobble

#endif
