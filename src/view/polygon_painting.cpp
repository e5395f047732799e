#include "view/polygon_painting.h"

#include "view/view_constants.h"

#include <QLineF>
#include <QPaintDevice>
#include <QPainter>
#include <QTransform>

#include <algorithm>
#include <cmath>
#include <vector>

namespace impetus::view {

namespace {

/// One family of hatch lines on the screen, y down: `sum` for x + y = c ("/", as
/// Qt::BDiagPattern), otherwise x − y = c ("\").
struct HatchFamily {
    bool sum = true;
    double value(QPointF p) const { return sum ? p.x() + p.y() : p.x() - p.y(); }
    /// The point of line c at abscissa x.
    QPointF at(double c, double x) const { return QPointF(x, sum ? c - x : x - c); }
};

/// Appends to `lines` the pieces of family `family`'s lines that lie inside `polygon` (device
/// pixels, odd-even rule), for the lines through pixel centres whose c is `anchor` plus a multiple
/// of the spacing, within [low, high].
void addHatchLines(const QPolygonF& polygon, HatchFamily family, double anchor, double low, double high,
                   std::vector<QLineF>& lines)
{
    const double spacing = constants::kHatchSpacingPx;
    double polygonLow = family.value(polygon.first());
    double polygonHigh = polygonLow;
    for (const QPointF& p : polygon) {
        polygonLow = std::min(polygonLow, family.value(p));
        polygonHigh = std::max(polygonHigh, family.value(p));
    }
    low = std::max(low, polygonLow);
    high = std::min(high, polygonHigh);
    if (!(low <= high))
        return;
    std::vector<double> crossings;
    const qsizetype n = polygon.size();
    for (double c = anchor + std::ceil((low - anchor) / spacing) * spacing; c <= high; c += spacing) {
        crossings.clear();
        for (qsizetype i = 0; i < n; ++i) {
            const QPointF a = polygon[i];
            const QPointF b = polygon[(i + 1) % n];
            const double fa = family.value(a) - c;
            const double fb = family.value(b) - c;
            // Half-open, so that a line through a vertex crosses one of its two edges, not both.
            if ((fa < 0) == (fb < 0))
                continue;
            const double t = fa / (fa - fb);
            crossings.push_back(a.x() + t * (b.x() - a.x()));
        }
        // Every line is diagonal, so x orders the crossings along it; inside between odd and even.
        std::sort(crossings.begin(), crossings.end());
        for (std::size_t k = 0; k + 1 < crossings.size(); k += 2)
            lines.emplace_back(family.at(c, crossings[k]), family.at(c, crossings[k + 1]));
    }
}

} // namespace

void fillPolygon(QPainter& painter, const QPolygonF& polygon, const QBrush& brush)
{
    painter.setPen(Qt::NoPen);
    painter.setBrush(brush);
    painter.drawPolygon(polygon, Qt::OddEvenFill);
}

void hatchPolygon(QPainter& painter, const QPolygonF& polygon, const QBrush& hatch)
{
    const bool backward = hatch.style() == Qt::BDiagPattern;
    const bool cross = hatch.style() == Qt::DiagCrossPattern;
    if (!backward && !cross) {
        fillPolygon(painter, polygon, hatch);
        return;
    }
    if (polygon.size() < 3)
        return;
    const QTransform toDevice = painter.deviceTransform();
    const QTransform world = painter.worldTransform();
    bool invertible = false;
    const QTransform worldInverse = world.inverted(&invertible);
    if (!invertible || !toDevice.isAffine())
        return;
    const QPolygonF device = toDevice.map(polygon);
    const QPointF origin = toDevice.map(QPointF(0, 0));
    if (!std::isfinite(origin.x()) || !std::isfinite(origin.y()))
        return;
    // The device's pixels: the lines are only worked out where they can show.
    double width = 0;
    double height = 0;
    if (const QPaintDevice* target = painter.device()) {
        width = target->width() * target->devicePixelRatioF();
        height = target->height() * target->devicePixelRatioF();
    }
    // Through the centre of the pixel at the origin: a pixel (i, j) has its centre at
    // (i + ½, j + ½), so x + y = i + j + 1 and x − y = i − j there.
    const double ox = std::round(origin.x());
    const double oy = std::round(origin.y());
    std::vector<QLineF> lines;
    addHatchLines(device, HatchFamily{true}, ox + oy + 1, 0, width + height, lines);
    if (cross)
        addHatchLines(device, HatchFamily{false}, ox - oy, -height, width, lines);
    if (lines.empty())
        return;

    // Drawn in device pixels, as a pattern brush is, whatever the world transform.
    const QTransform screen = worldInverse * toDevice; // the device's own part (pixel ratio)
    painter.save();
    painter.setWorldTransform(screen.inverted());
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(QPen(hatch.color(), 0)); // a cosmetic one-pixel pen
    painter.setBrush(Qt::NoBrush);
    painter.drawLines(lines.data(), static_cast<int>(lines.size()));
    painter.restore();
}

void strokePolygon(QPainter& painter, const QPolygonF& polygon, const QPen& pen)
{
    painter.setBrush(Qt::NoBrush);
    const bool asLines = pen.isCosmetic() && pen.style() == Qt::SolidLine &&
                         pen.widthF() <= constants::kEdgeLinesMaxWidthPx && polygon.size() >= 2;
    if (!asLines) {
        painter.setPen(pen);
        painter.drawPolygon(polygon);
        return;
    }
    QPen edges = pen;
    edges.setCapStyle(Qt::SquareCap);
    painter.setPen(edges);
    std::vector<QLineF> lines;
    lines.reserve(static_cast<std::size_t>(polygon.size()));
    for (qsizetype i = 0; i < polygon.size(); ++i)
        lines.emplace_back(polygon[i], polygon[(i + 1) % polygon.size()]);
    painter.drawLines(lines.data(), static_cast<int>(lines.size()));
}

} // namespace impetus::view
