#include "view/body_stamps.h"

#include "view/view_constants.h"

#include <QPainter>
#include <QTransform>

#include <cmath>

namespace impetus::view {

namespace {

/// Relative tolerance on the painter's transform being a rotation with uniform scale: far below
/// what a pixel could show, far above rounding.
constexpr double kSimilarityTolerance = 1e-9;
/// Transparent pixels kept round a stamp's outline, px: room for antialiasing.
constexpr int kStampMarginPx = 2;

} // namespace

bool BodyStamps::drawCircle(QPainter& painter, const QPainterPath& outline, double radius, const QBrush& fill,
                            const QPen& pen)
{
    if (!painter.testRenderHint(QPainter::Antialiasing) || fill.style() != Qt::SolidPattern || !pen.isCosmetic() ||
        pen.style() != Qt::SolidLine || pen.brush().style() != Qt::SolidPattern)
        return false;
    // The transform to device pixels (the world's, and the screen's pixel ratio) must keep
    // circles circles: rows of equal length, at right angles.
    const QTransform toDevice = painter.deviceTransform();
    if (!toDevice.isAffine())
        return false;
    const double rowA = toDevice.m11() * toDevice.m11() + toDevice.m12() * toDevice.m12();
    const double rowB = toDevice.m21() * toDevice.m21() + toDevice.m22() * toDevice.m22();
    const double across = toDevice.m11() * toDevice.m21() + toDevice.m12() * toDevice.m22();
    if (!(rowA > 0) || std::abs(rowA - rowB) > kSimilarityTolerance * rowA ||
        std::abs(across) > kSimilarityTolerance * rowA)
        return false;
    const double scale = std::sqrt(rowA);
    const QPointF centre = toDevice.map(QPointF(0, 0));
    if (!std::isfinite(centre.x()) || !std::isfinite(centre.y()))
        return false;

    // The centre on the stamp grid: a whole pixel and a step within it.
    constexpr int kSteps = constants::kStampSubpixelSteps;
    const auto split = [](double at, int& whole, int& sub) {
        double pixel = std::floor(at);
        sub = static_cast<int>(std::lround((at - pixel) * kSteps));
        if (sub == kSteps) {
            sub = 0;
            pixel += 1;
        }
        whole = static_cast<int>(pixel);
    };
    int x = 0;
    int y = 0;
    Key key{fill.color().rgba(), pen.color().rgba(), pen.widthF(), radius * scale, 0, 0};
    split(centre.x(), x, key.subX);
    split(centre.y(), y, key.subY);

    auto found = m_images.find(key);
    if (found == m_images.end()) {
        if (m_images.size() >= constants::kMaxBodyStamps)
            m_images.clear();
        // A square with the circle's centre at half its side plus the step, and room for the
        // outline's half width and antialiasing all round.
        const int half = static_cast<int>(std::ceil(key.radius + key.penWidth / 2)) + kStampMarginPx;
        QImage image(2 * half, 2 * half, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::transparent);
        QPainter stamp(&image);
        stamp.setRenderHint(QPainter::Antialiasing);
        stamp.translate(half + static_cast<double>(key.subX) / kSteps, half + static_cast<double>(key.subY) / kSteps);
        stamp.scale(scale, scale);
        // As BodyItem::paint draws it: the fill, then the outline over it.
        stamp.setPen(Qt::NoPen);
        stamp.setBrush(fill);
        stamp.drawPath(outline);
        stamp.setPen(pen);
        stamp.setBrush(Qt::NoBrush);
        stamp.drawPath(outline);
        stamp.end();
        found = m_images.emplace(key, std::move(image)).first;
    }

    // Drawn one to one in device pixels: the world transform that makes the device transform a
    // pure translation to the stamp's corner.
    const QImage& image = found->second;
    const QTransform world = painter.worldTransform();
    const QTransform screen = world.inverted() * toDevice; // the device's own part (pixel ratio)
    const int half = image.width() / 2;
    painter.setWorldTransform(QTransform::fromTranslate(x - half, y - half) * screen.inverted());
    painter.drawImage(QPointF(0, 0), image);
    painter.setWorldTransform(world);
    return true;
}

} // namespace impetus::view
