#pragma once
/// \file body_stamps.h
/// Pictures of round bodies drawn once and stamped at each body's place, so that a canvas of
/// thousands of circles does not flatten and rasterise each circle's curve on every paint.

#include <QBrush>
#include <QImage>
#include <QPainterPath>
#include <QPen>
#include <QRgb>

#include <compare>
#include <cstddef>
#include <map>

class QPainter;

namespace impetus::view {

/// A cache of circle pictures (fill and outline), one per fill colour, outline colour and width,
/// radius on screen and position within a pixel (in steps of 1/constants::kStampSubpixelSteps
/// px). A circle looks the same at every angle, so one picture serves every body of that look
/// and size however it turns; what shows the turn (the radius line) is drawn by the body.
///
/// A stamp differs from drawing the circle in place only in its edge pixels' antialiasing: its
/// centre lies within 1/(2·kStampSubpixelSteps) px of the true one, and the curve is flattened
/// unturned. Inside and outside the edge the pixels are the same.
class BodyStamps {
public:
    /// Draws the circle `outline` (centred on the origin, radius `radius` in the painter's
    /// coordinates) filled with `fill` and outlined with the cosmetic `pen`, as drawing the path
    /// twice would. Returns false, drawing nothing, when a stamp cannot stand in for that: the
    /// painter maps its coordinates other than by a rotation, reflection and uniform scale, does
    /// not antialias, or the fill is not one plain colour.
    bool drawCircle(QPainter& painter, const QPainterPath& outline, double radius, const QBrush& fill,
                    const QPen& pen);

    /// Pictures kept.
    std::size_t size() const { return m_images.size(); }

private:
    /// What one picture shows.
    struct Key {
        QRgb fill = 0;
        QRgb pen = 0;
        double penWidth = 0; ///< px
        double radius = 0; ///< px
        int subX = 0; ///< centre within its pixel, in 1/kStampSubpixelSteps px
        int subY = 0;
        auto operator<=>(const Key&) const = default;
    };
    std::map<Key, QImage> m_images;
};

} // namespace impetus::view
