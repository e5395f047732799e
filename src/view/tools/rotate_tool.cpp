#include "view/tools/rotate_tool.h"

#include "view/canvas_view.h"
#include "view/lesson_session.h"
#include "view/view_constants.h"

#include <QKeyEvent>
#include <QPainter>

#include <cmath>
#include <numbers>

namespace impetus::view {

namespace {

double angleOf(const Vec2& v) { return std::atan2(v.y(), v.x()); }

Vec2 rotated(const Vec2& v, double angle)
{
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

} // namespace

std::optional<QString> RotationGesture::begin(SceneDocument& document, std::vector<int> bodies,
                                             const QPointF& scenePos, const LessonSession* lesson)
{
    if (bodies.empty())
        return std::nullopt;
    if (std::optional<QString> lock = poseLockOf(lesson, bodies, false, true))
        return lock;
    m_bodies = std::move(bodies);
    m_startPoses.clear();
    m_pivot = Vec2::Zero();
    for (const int i : m_bodies) {
        const model::BodyState& state = document.world().bodies[static_cast<std::size_t>(i)].state;
        m_startPoses.push_back({state.position, state.angle});
        m_pivot += state.position;
    }
    m_pivot /= static_cast<double>(m_bodies.size());
    m_start = scenePos;
    m_gesture = document.newGesture();
    m_active = true;
    return std::nullopt;
}

void RotationGesture::update(SceneDocument& document, const QPointF& scenePos, bool snap)
{
    if (!m_active)
        return;
    const Vec2 from = toVec2(m_start) - m_pivot;
    const Vec2 to = toVec2(scenePos) - m_pivot;
    if (from.norm() == 0 || to.norm() == 0)
        return;
    double turn = angleOf(to) - angleOf(from);
    if (snap) {
        const double step = constants::kRotationSnapDegrees * std::numbers::pi / 180;
        turn = std::round(turn / step) * step;
    }
    std::vector<BodyPose> poses;
    poses.reserve(m_startPoses.size());
    for (const BodyPose& start : m_startPoses)
        poses.push_back({m_pivot + rotated(start.position - m_pivot, turn), start.angle + turn});
    document.setPoses(m_bodies, poses, tr("Rotate"), m_gesture);
}

void RotationGesture::cancel(SceneDocument& document)
{
    if (!m_active)
        return;
    document.setPoses(m_bodies, m_startPoses, tr("Rotate"), m_gesture);
    end();
}

void paintRotation(QPainter& painter, double pixelsPerMetre, const QPointF& pivot, const QPointF& cursor)
{
    QPen pen(constants::kSelectionColor, constants::kOutlineWidthPx, Qt::DashLine);
    pen.setCosmetic(true);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    painter.drawLine(pivot, cursor);
    const double r = constants::kPinMarkerRadiusPx / pixelsPerMetre;
    painter.drawEllipse(pivot, r, r);
}

void RotateTool::cancel() { m_rotation.end(); }

void RotateTool::mousePress(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    m_cursor = event.scenePos;
    std::vector<int> bodies = m_document.selection().bodies;
    if (const std::optional<int> hit = m_canvas.bodyAt(event.scenePos);
        hit && std::ranges::find(bodies, *hit) == bodies.end()) {
        bodies = {*hit};
        m_document.setSelection(Selection{bodies, {}, {}});
    }
    if (const std::optional<QString> lock = m_rotation.begin(m_document, bodies, event.scenePos, m_canvas.lessonSession()))
        m_canvas.showMessage(event.scenePos, *lock);
}

void RotateTool::mouseMove(const ToolEvent& event)
{
    m_cursor = event.scenePos;
    m_rotation.update(m_document, event.scenePos, event.modifiers.testFlag(Qt::ShiftModifier));
}

void RotateTool::mouseRelease(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    // The release decides the final angle, with the modifiers held at that moment.
    m_rotation.update(m_document, event.scenePos, event.modifiers.testFlag(Qt::ShiftModifier));
    m_rotation.end();
}

bool RotateTool::wantsKey(int key, Qt::KeyboardModifiers) const
{
    return m_rotation.isActive() && key == Qt::Key_Escape;
}

bool RotateTool::keyPress(QKeyEvent* event)
{
    if (!wantsKey(event->key(), event->modifiers()))
        return false;
    m_rotation.cancel(m_document);
    return true;
}

void RotateTool::paintOverlay(QPainter& painter, double pixelsPerMetre) const
{
    if (m_rotation.isActive())
        paintRotation(painter, pixelsPerMetre, m_rotation.pivot(), m_cursor);
}

} // namespace impetus::view
