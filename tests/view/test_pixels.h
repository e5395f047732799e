#pragma once
/// \file test_pixels.h
/// Finding what the canvas drew in a grab, for the view tests.

#include <QColor>
#include <QImage>
#include <QPoint>
#include <QRect>

#include <cstdlib>

namespace impetus::view::test {

/// Pixels of `image` within a small distance of `colour` (antialiased edges blend into the paper),
/// inside `region` (the whole image when null); their centroid goes to `centroid`.
inline int pixelsNear(const QImage& image, const QColor& colour, QPoint* centroid = nullptr, QRect region = {})
{
    if (region.isNull())
        region = image.rect();
    region = region.intersected(image.rect());
    int count = 0;
    long long sx = 0;
    long long sy = 0;
    for (int y = region.top(); y <= region.bottom(); ++y) {
        for (int x = region.left(); x <= region.right(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                    std::abs(c.blue() - colour.blue()) <=
                24) {
                ++count;
                sx += x;
                sy += y;
            }
        }
    }
    if (centroid && count > 0)
        *centroid = QPoint(static_cast<int>(sx / count), static_cast<int>(sy / count));
    return count;
}

} // namespace impetus::view::test
