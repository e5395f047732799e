#pragma once
/// \file color.h
/// A body's display colour, kept in the model as plain sRGB bytes (no Qt in the engine).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace impetus::model {

/// An sRGB colour, 8 bits per channel; written in scenes as "#rrggbb".
struct Color {
    std::uint8_t r = 0x3b; ///< red, 0–255
    std::uint8_t g = 0x82; ///< green, 0–255
    std::uint8_t b = 0xf6; ///< blue, 0–255

    bool operator==(const Color&) const = default; ///< memberwise equality

    /// "#rrggbb", lower case.
    std::string toHex() const;

    /// Parses "#rrggbb" (either case); nullopt for anything else.
    static std::optional<Color> fromHex(std::string_view text);
};

} // namespace impetus::model
