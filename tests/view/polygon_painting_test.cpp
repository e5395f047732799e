// The quick ways of painting a polygon body (polygon_painting.h) against Qt's own: the fill and a
// thin outline match a painted path but for antialiasing at the corners, a thick outline is the
// path's stroke exactly, and the hatch lies on one pixel diagonal every 8 px inside the polygon,
// not turned with the body but moved with it, as a pattern brush does.

#include "view/polygon_painting.h"
#include "view/view_constants.h"

#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

using namespace impetus::view;
namespace constants = impetus::view::constants;

namespace {

constexpr int kSide = 240;

/// An L: concave, so that the odd-even pairing of a hatch line's crossings and the fill of a
/// non-convex polygon are both tried. Metres, about its centre.
QPolygonF lShape()
{
    return QPolygonF({QPointF(-1, -1), QPointF(1.2, -1), QPointF(1.2, -0.3), QPointF(-0.3, -0.3), QPointF(-0.3, 1),
                      QPointF(-1, 1)});
}

/// A painter on `image` as the canvas has one on a body: y up, 60 px per metre, the body turned
/// by `degrees` about its centre at `centre` (px).
void placeBody(QPainter& painter, QPointF centre, double degrees)
{
    painter.setRenderHint(QPainter::Antialiasing);
    painter.translate(centre);
    painter.scale(60, -60);
    painter.rotate(degrees);
}

QImage blank()
{
    QImage image(kSide, kSide, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    return image;
}

/// Largest difference of one channel between two pictures, over the pixels where `where` holds.
template <typename Where>
int largestDifference(const QImage& a, const QImage& b, Where where)
{
    int largest = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (where(x, y)) {
                const QRgb p = a.pixel(x, y);
                const QRgb q = b.pixel(x, y);
                largest = std::max({largest, std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                                    std::abs(qBlue(p) - qBlue(q))});
            }
    return largest;
}

/// Distance from pixel (x, y)'s centre to the nearest of `points` (px).
double distanceToNearest(int x, int y, const QPolygonF& points)
{
    double nearest = 1e300;
    for (const QPointF& p : points)
        nearest = std::min(nearest, std::hypot(x + 0.5 - p.x(), y + 0.5 - p.y()));
    return nearest;
}

/// Pixels darker than mid-grey.
std::vector<QPoint> darkPixels(const QImage& image)
{
    std::vector<QPoint> dark;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (qRed(image.pixel(x, y)) < 128)
                dark.emplace_back(x, y);
    return dark;
}

/// The L turned by 30° at (120.4, 119.7) px, hatched with `style`; its outline in pixels to `device`.
QImage hatched(Qt::BrushStyle style, QPointF centre, QPolygonF* device = nullptr)
{
    QImage image = blank();
    QPainter painter(&image);
    placeBody(painter, centre, 30);
    hatchPolygon(painter, lShape(), QBrush(Qt::black, style));
    if (device)
        *device = painter.deviceTransform().map(lShape());
    return image;
}

/// Area of the closed polygon, px².
double areaOf(const QPolygonF& polygon)
{
    double twice = 0;
    for (qsizetype i = 0; i < polygon.size(); ++i) {
        const QPointF a = polygon[i];
        const QPointF b = polygon[(i + 1) % polygon.size()];
        twice += a.x() * b.y() - b.x() * a.y();
    }
    return std::abs(twice) / 2;
}

} // namespace

class PolygonPaintingTest : public QObject {
    Q_OBJECT

private slots:
    void fillIsThePathsFillButForEdgeAntialiasing();
    void thinOutlineIsThePathsStrokeAwayFromTheCorners();
    void thickOutlineIsThePathsStrokeExactly();
    void hatchIsOnePixelDiagonalEveryEightPixelsInside();
    void hatchMovesWithTheBodyButDoesNotTurn();
    void crossHatchHasBothDiagonals();
    void degenerateInputDrawsNothing();
};

void PolygonPaintingTest::fillIsThePathsFillButForEdgeAntialiasing()
{
    QImage byPath = blank();
    QImage byPolygon = blank();
    QPolygonF device;
    {
        QPainter painter(&byPath);
        placeBody(painter, QPointF(120.3, 119.6), 23);
        QPainterPath path;
        path.addPolygon(lShape());
        path.closeSubpath();
        painter.setPen(Qt::NoPen);
        painter.setBrush(Qt::darkBlue);
        painter.drawPath(path);
        device = painter.deviceTransform().map(lShape());
    }
    {
        QPainter painter(&byPolygon);
        placeBody(painter, QPointF(120.3, 119.6), 23);
        fillPolygon(painter, lShape(), QBrush(Qt::darkBlue));
    }
    // Inside and outside, more than a pixel from every edge, the two are the same colour.
    const QPainterPath inside = [&] {
        QPainterPath p;
        p.addPolygon(device);
        p.closeSubpath();
        return p;
    }();
    const auto awayFromEdges = [&](int x, int y) {
        const QPointF c(x + 0.5, y + 0.5);
        for (const QPointF& d : {QPointF(1.5, 0), QPointF(-1.5, 0), QPointF(0, 1.5), QPointF(0, -1.5)})
            if (inside.contains(c) != inside.contains(c + d))
                return false;
        return true;
    };
    QCOMPARE(largestDifference(byPath, byPolygon, awayFromEdges), 0);
    // At the edges only the antialiased coverage may differ, and the amount of paint is the same
    // to a thousandth (the two rasterisers sample coverage differently).
    long long inkPath = 0;
    long long inkPolygon = 0;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            inkPath += 255 - qRed(byPath.pixel(x, y));
            inkPolygon += 255 - qRed(byPolygon.pixel(x, y));
        }
    QVERIFY(inkPath > 0);
    QVERIFY2(std::abs(inkPath - inkPolygon) < inkPath / 1000,
             qPrintable(QStringLiteral("paint %1 against the path's %2").arg(inkPolygon).arg(inkPath)));
}

void PolygonPaintingTest::thinOutlineIsThePathsStrokeAwayFromTheCorners()
{
    QPen pen(Qt::black, constants::kOutlineWidthPx);
    pen.setCosmetic(true);
    pen.setJoinStyle(Qt::RoundJoin);
    QImage byPath = blank();
    QImage byLines = blank();
    QPolygonF device;
    {
        QPainter painter(&byPath);
        placeBody(painter, QPointF(120.3, 119.6), 23);
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        painter.drawPolygon(lShape());
        device = painter.deviceTransform().map(lShape());
    }
    {
        QPainter painter(&byLines);
        placeBody(painter, QPointF(120.3, 119.6), 23);
        strokePolygon(painter, lShape(), pen);
    }
    // Along the edges the square-capped lines are the stroke: more than two pixels from every
    // corner no channel differs by more than an eighth of its range (the two strokers' coverage).
    const int alongEdges = largestDifference(byPath, byLines, [&](int x, int y) { return distanceToNearest(x, y, device) > 2; });
    QVERIFY2(alongEdges <= 32, qPrintable(QStringLiteral("%1 along the edges").arg(alongEdges)));
    // At a corner the two edges' lines meet, each antialiased on its own, and are laid one over the
    // other: coverages a and b of a pixel give 1 − (1 − a)(1 − b). Where their parts of the pixel
    // do not overlap, the stroke's one shape covers a + b: lighter by ab; where they do, it covers
    // max(a, b): darker by at most ab. ab is a quarter of the range at most (a = b = ½). Beyond
    // that the square caps cover the round join's disc and, at a right angle, a corner of
    // (w/2)²(1 − π/4) px² outside it (w the width): darker by that much more.
    int lighter = 0;
    int darker = 0;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const int difference = qRed(byPath.pixel(x, y)) - qRed(byLines.pixel(x, y));
            darker = std::max(darker, difference);
            lighter = std::max(lighter, -difference);
        }
    QVERIFY2(lighter <= 255 / 4, qPrintable(QStringLiteral("%1 lighter").arg(lighter)));
    const double halfWidth = constants::kOutlineWidthPx / 2;
    const double capCorner = halfWidth * halfWidth * (1 - M_PI / 4);
    QVERIFY2(darker <= 255 * (0.25 + capCorner), qPrintable(QStringLiteral("%1 darker").arg(darker)));
}

void PolygonPaintingTest::thickOutlineIsThePathsStrokeExactly()
{
    QPen pen(Qt::black, 2.5 * constants::kOutlineWidthPx); // projector mode's thick lines
    pen.setCosmetic(true);
    pen.setJoinStyle(Qt::RoundJoin);
    QVERIFY(pen.widthF() > constants::kEdgeLinesMaxWidthPx);
    QImage byPath = blank();
    QImage byHelper = blank();
    {
        QPainter painter(&byPath);
        placeBody(painter, QPointF(120.3, 119.6), 23);
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        painter.drawPolygon(lShape());
    }
    {
        QPainter painter(&byHelper);
        placeBody(painter, QPointF(120.3, 119.6), 23);
        strokePolygon(painter, lShape(), pen);
    }
    QCOMPARE(byHelper, byPath);
}

void PolygonPaintingTest::hatchIsOnePixelDiagonalEveryEightPixelsInside()
{
    QPolygonF device;
    const QImage ours = hatched(Qt::BDiagPattern, QPointF(120.4, 119.7), &device);
    const std::vector<QPoint> dark = darkPixels(ours);
    QVERIFY(!dark.empty());
    const auto spacing = static_cast<int>(constants::kHatchSpacingPx);
    // All on one family of "/" diagonals, x + y the same modulo the spacing, as Qt::BDiagPattern's.
    std::set<int> residues;
    for (const QPoint& p : dark)
        residues.insert((p.x() + p.y()) % spacing);
    QCOMPARE(residues.size(), std::size_t{1});
    // Inside the polygon, or on its edge (a one-pixel line's pixels reach half a pixel past it).
    QPainterPath grown;
    grown.addPolygon(device);
    grown.closeSubpath();
    QPainterPathStroker edge;
    edge.setWidth(2.5);
    grown = grown.united(edge.createStroke(grown));
    for (const QPoint& p : dark)
        QVERIFY2(grown.contains(QPointF(p) + QPointF(0.5, 0.5)), qPrintable(QStringLiteral("pixel %1, %2").arg(p.x()).arg(p.y())));
    // One pixel in eight of the area, as the pattern's density, and as many as Qt's pattern
    // brush paints on the same polygon, to the pixels its lines' ends may gain or lose at the edge.
    const double area = areaOf(device);
    QImage qts = blank();
    {
        QPainter painter(&qts);
        placeBody(painter, QPointF(120.4, 119.7), 30);
        painter.setPen(Qt::NoPen);
        painter.setBrush(QBrush(Qt::black, Qt::BDiagPattern));
        painter.drawPolygon(lShape());
    }
    const auto qtCount = static_cast<double>(darkPixels(qts).size());
    const auto count = static_cast<double>(dark.size());
    // A line's two ends gain or lose at most a pixel each: the L's perimeter in pixels, over the
    // spacing, lines end at its edges.
    double perimeter = 0;
    for (qsizetype i = 0; i < device.size(); ++i)
        perimeter += std::hypot(device[i].x() - device[(i + 1) % device.size()].x(),
                                device[i].y() - device[(i + 1) % device.size()].y());
    const double ends = 2 * perimeter / constants::kHatchSpacingPx;
    QVERIFY2(std::abs(count - area / constants::kHatchSpacingPx) <= ends,
             qPrintable(QStringLiteral("%1 pixels for an area of %2 px²").arg(count).arg(area)));
    QVERIFY2(std::abs(count - qtCount) <= ends,
             qPrintable(QStringLiteral("%1 pixels against the pattern brush's %2").arg(count).arg(qtCount)));
}

void PolygonPaintingTest::hatchMovesWithTheBodyButDoesNotTurn()
{
    const auto spacing = static_cast<int>(constants::kHatchSpacingPx);
    const auto residueOf = [&](const QImage& image) {
        const std::vector<QPoint> dark = darkPixels(image);
        return dark.empty() ? -1 : (dark.front().x() + dark.front().y()) % spacing;
    };
    const int here = residueOf(hatched(Qt::BDiagPattern, QPointF(120.4, 119.7)));
    // Three pixels to the right: the lines move with the body by three pixels.
    const int moved = residueOf(hatched(Qt::BDiagPattern, QPointF(123.4, 119.7)));
    QVERIFY(here >= 0);
    QCOMPARE(moved, (here + 3) % spacing);
    // Turned another way, the lines are still "/" diagonals: a single family again.
    QImage turned = blank();
    {
        QPainter painter(&turned);
        placeBody(painter, QPointF(120.4, 119.7), -65);
        hatchPolygon(painter, lShape(), QBrush(Qt::black, Qt::BDiagPattern));
    }
    std::set<int> residues;
    for (const QPoint& p : darkPixels(turned))
        residues.insert((p.x() + p.y()) % spacing);
    QCOMPARE(residues.size(), std::size_t{1});
}

void PolygonPaintingTest::crossHatchHasBothDiagonals()
{
    QPolygonF device;
    const QImage image = hatched(Qt::DiagCrossPattern, QPointF(120.4, 119.7), &device);
    const auto spacing = static_cast<int>(constants::kHatchSpacingPx);
    const std::vector<QPoint> dark = darkPixels(image);
    // Each pixel on a "/" or a "\" diagonal; the most common residue of each family holds them all.
    std::map<int, int> sums;
    std::map<int, int> differences;
    for (const QPoint& p : dark) {
        ++sums[(p.x() + p.y()) % spacing];
        ++differences[((p.x() - p.y()) % spacing + spacing) % spacing];
    }
    const auto mostCommon = [](const std::map<int, int>& counts) {
        return std::max_element(counts.begin(), counts.end(), [](auto a, auto b) { return a.second < b.second; })->first;
    };
    const int sum = mostCommon(sums);
    const int difference = mostCommon(differences);
    int slash = 0;
    int backslash = 0;
    for (const QPoint& p : dark) {
        const bool onSlash = (p.x() + p.y()) % spacing == sum;
        const bool onBackslash = ((p.x() - p.y()) % spacing + spacing) % spacing == difference;
        QVERIFY2(onSlash || onBackslash, qPrintable(QStringLiteral("pixel %1, %2").arg(p.x()).arg(p.y())));
        slash += onSlash ? 1 : 0;
        backslash += onBackslash ? 1 : 0;
    }
    // Each family about an eighth of the area (less the pixels where the two cross).
    const double eighth = areaOf(device) / constants::kHatchSpacingPx;
    QVERIFY2(slash > 0.8 * eighth && backslash > 0.8 * eighth,
             qPrintable(QStringLiteral("%1 and %2 pixels for an eighth of %3").arg(slash).arg(backslash).arg(eighth)));
}

void PolygonPaintingTest::degenerateInputDrawsNothing()
{
    QImage image = blank();
    const QImage before = image;
    QPainter painter(&image);
    placeBody(painter, QPointF(120, 120), 10);
    // Two points: no area to hatch or fill.
    hatchPolygon(painter, QPolygonF({QPointF(0, 0), QPointF(1, 1)}), QBrush(Qt::black, Qt::BDiagPattern));
    // A painter that squashes everything to a line (zero scale): nothing to invert, nothing drawn.
    painter.scale(0, 1);
    hatchPolygon(painter, lShape(), QBrush(Qt::black, Qt::DiagCrossPattern));
    painter.end();
    QCOMPARE(image, before);
}

QTEST_MAIN(PolygonPaintingTest)
#include "polygon_painting_test.moc"
