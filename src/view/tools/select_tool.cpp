#include "view/tools/select_tool.h"

#include "view/canvas_view.h"
#include "view/lesson_session.h"
#include "view/view_constants.h"

#include <QKeyEvent>
#include <QLineF>
#include <QPainter>

#include <algorithm>

namespace impetus::view {

namespace {

/// `list` with `index` added, or removed when it was there; sorted.
std::vector<int> toggled(std::vector<int> list, int index)
{
    if (const auto it = std::ranges::find(list, index); it != list.end())
        list.erase(it);
    else
        list.push_back(index);
    std::ranges::sort(list);
    return list;
}

bool contains(const std::vector<int>& list, int index) { return std::ranges::find(list, index) != list.end(); }

bool isArrow(int key) { return key == Qt::Key_Left || key == Qt::Key_Right || key == Qt::Key_Up || key == Qt::Key_Down; }

/// The union of two selections.
Selection united(Selection a, const Selection& b)
{
    const auto merge = [](std::vector<int>& into, const std::vector<int>& from) {
        into.insert(into.end(), from.begin(), from.end());
        std::ranges::sort(into);
        into.erase(std::unique(into.begin(), into.end()), into.end());
    };
    merge(a.bodies, b.bodies);
    merge(a.springs, b.springs);
    merge(a.joints, b.joints);
    return a;
}

} // namespace

void SelectTool::cancel()
{
    m_mode = Mode::Idle;
    m_rotation.end();
}

void SelectTool::mousePress(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    m_pressPos = event.scenePos;
    m_cursor = event.scenePos;
    const bool shift = event.modifiers.testFlag(Qt::ShiftModifier);
    Selection selection = m_document.selection();

    if (const std::optional<int> body = m_canvas.bodyAt(event.scenePos)) {
        if (shift)
            selection.bodies = toggled(selection.bodies, *body);
        else if (!contains(selection.bodies, *body))
            selection = Selection{{*body}, {}, {}};
        m_document.setSelection(selection);
        const std::vector<int> bodies = m_document.selection().bodies;
        if (!contains(bodies, *body))
            return; // Shift took it out of the selection: nothing to drag.
        if (event.modifiers.testFlag(Qt::ControlModifier)) {
            beginRotation(bodies, event.scenePos);
            return;
        }
        // A body the lesson locks is selected (the pane shows it) but does not move; the canvas
        // says why once the user tries to drag it.
        if (std::optional<QString> lock = poseLockOf(m_canvas.lessonSession(), bodies, true, false)) {
            m_lockMessage = std::move(*lock);
            m_mode = Mode::Locked;
            return;
        }
        m_moving = bodies;
        m_startPoses.clear();
        for (const int i : m_moving) {
            const model::BodyState& state = m_document.world().bodies[static_cast<std::size_t>(i)].state;
            m_startPoses.push_back({state.position, state.angle});
        }
        m_gesture = m_document.newGesture();
        m_mode = Mode::Moving;
        return;
    }
    if (const std::optional<int> joint = m_canvas.jointAt(event.scenePos)) {
        if (shift)
            selection.joints = toggled(selection.joints, *joint);
        else
            selection = Selection{{}, {}, {*joint}};
        m_document.setSelection(selection);
        return;
    }
    if (const std::optional<int> spring = m_canvas.springAt(event.scenePos)) {
        if (shift)
            selection.springs = toggled(selection.springs, *spring);
        else
            selection = Selection{{}, {*spring}, {}};
        m_document.setSelection(selection);
        return;
    }
    if (event.modifiers.testFlag(Qt::ControlModifier) && !selection.bodies.empty()) {
        beginRotation(selection.bodies, event.scenePos);
        return;
    }
    m_selectionBefore = shift ? selection : Selection{};
    m_document.setSelection(m_selectionBefore);
    m_mode = Mode::RubberBand;
}

void SelectTool::beginRotation(const std::vector<int>& bodies, const QPointF& scenePos)
{
    if (std::optional<QString> lock = m_rotation.begin(m_document, bodies, scenePos, m_canvas.lessonSession())) {
        m_canvas.showMessage(scenePos, *lock);
        m_mode = Mode::Idle;
        return;
    }
    m_mode = Mode::Rotating;
}

void SelectTool::mouseMove(const ToolEvent& event)
{
    m_cursor = event.scenePos;
    switch (m_mode) {
    case Mode::Locked:
        if (event.scenePos != m_pressPos) {
            m_canvas.showMessage(event.scenePos, m_lockMessage);
            m_mode = Mode::Idle;
        }
        break;
    case Mode::Moving:
        moveTo(event.scenePos);
        break;
    case Mode::Rotating:
        m_rotation.update(m_document, event.scenePos, event.modifiers.testFlag(Qt::ShiftModifier));
        break;
    case Mode::RubberBand:
        m_document.setSelection(united(m_selectionBefore, m_canvas.itemsInside(QRectF(m_pressPos, m_cursor))));
        break;
    case Mode::Idle:
        break;
    }
}

void SelectTool::moveTo(const QPointF& scenePos)
{
    // The body that was grabbed first leads: its centre goes to a grid crossing when snapping, and
    // the others keep their places relative to it.
    const QPointF delta = scenePos - m_pressPos;
    if (delta.isNull() || m_startPoses.empty())
        return;
    const QPointF leadStart = toQPointF(m_startPoses.front().position);
    const Vec2 offset = toVec2(m_canvas.snapped(leadStart + delta) - leadStart);
    std::vector<BodyPose> poses = m_startPoses;
    for (BodyPose& pose : poses)
        pose.position += offset;
    m_document.setPoses(m_moving, poses, tr("Move"), m_gesture);
}

void SelectTool::mouseRelease(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    if (m_mode == Mode::Moving)
        moveTo(event.scenePos);
    if (m_mode == Mode::Rotating)
        m_rotation.update(m_document, event.scenePos, event.modifiers.testFlag(Qt::ShiftModifier));
    m_rotation.end();
    m_mode = Mode::Idle;
}

bool SelectTool::wantsKey(int key, Qt::KeyboardModifiers modifiers) const
{
    const Qt::KeyboardModifiers other = modifiers & ~(Qt::ShiftModifier | Qt::KeypadModifier);
    if (other != Qt::NoModifier)
        return false;
    if (isArrow(key))
        return !m_document.selection().bodies.empty();
    return key == Qt::Key_Escape && (m_mode != Mode::Idle || !m_document.selection().empty());
}

bool SelectTool::keyPress(QKeyEvent* event)
{
    if (!wantsKey(event->key(), event->modifiers()))
        return false;
    if (event->key() == Qt::Key_Escape) {
        switch (m_mode) {
        case Mode::Moving:
            // Back to the start poses within the same gesture: the drag's command then changes
            // nothing and leaves the undo stack.
            m_document.setPoses(m_moving, m_startPoses, tr("Move"), m_gesture);
            break;
        case Mode::Rotating:
            m_rotation.cancel(m_document);
            break;
        case Mode::RubberBand:
            m_document.setSelection(m_selectionBefore);
            break;
        case Mode::Locked:
        case Mode::Idle:
            m_document.setSelection({});
            break;
        }
        m_mode = Mode::Idle;
        return true;
    }
    double step = constants::kNudgeGridFraction * m_canvas.gridSpacing();
    if (event->modifiers().testFlag(Qt::ShiftModifier))
        step *= constants::kNudgeLargeFactor;
    Vec2 offset = Vec2::Zero();
    switch (event->key()) {
    case Qt::Key_Left:
        offset.x() = -step;
        break;
    case Qt::Key_Right:
        offset.x() = step;
        break;
    case Qt::Key_Up:
        offset.y() = step;
        break;
    default:
        offset.y() = -step;
        break;
    }
    const std::vector<int> bodies = m_document.selection().bodies;
    if (const std::optional<QString> lock = poseLockOf(m_canvas.lessonSession(), bodies, true, false)) {
        const model::BodyState& state = m_document.world().bodies[static_cast<std::size_t>(bodies.front())].state;
        m_canvas.showMessage(toQPointF(state.position), *lock);
        return true;
    }
    std::vector<BodyPose> poses;
    for (const int i : bodies) {
        const model::BodyState& state = m_document.world().bodies[static_cast<std::size_t>(i)].state;
        poses.push_back({state.position + offset, state.angle});
    }
    m_document.setPoses(bodies, poses, tr("Nudge"), m_document.newGesture());
    return true;
}

void SelectTool::paintOverlay(QPainter& painter, double pixelsPerMetre) const
{
    if (m_mode == Mode::Rotating && m_rotation.isActive()) {
        paintRotation(painter, pixelsPerMetre, m_rotation.pivot(), m_cursor);
        return;
    }
    if (m_mode != Mode::RubberBand)
        return;
    QPen pen(constants::kPreviewColor, 1, Qt::DashLine);
    pen.setCosmetic(true);
    painter.setPen(pen);
    QColor fill = constants::kPreviewColor;
    // QColor keeps its alpha as a float; the constant is a double like every other.
    fill.setAlphaF(static_cast<float>(constants::kRubberBandFillAlpha));
    painter.setBrush(fill);
    painter.drawRect(QRectF(m_pressPos, m_cursor).normalized());
}

} // namespace impetus::view
