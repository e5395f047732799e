#include "view/tools/trace_point_tool.h"

#include "view/canvas_instruments.h"
#include "view/canvas_view.h"
#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include <QKeyEvent>
#include <QLineF>

namespace impetus::view {

void TracePointTool::mousePress(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    const std::optional<int> hit = m_canvas.bodyAt(event.scenePos);
    if (!hit)
        return;
    const auto body = static_cast<std::uint32_t>(*hit);
    CanvasInstruments& instruments = m_canvas.instruments();
    for (const TracedPoint& traced : instruments.tracedPoints()) {
        if (traced.body != body)
            continue;
        const Vec2 at = instruments.worldPoint(body, traced.local);
        const QPointF now = m_canvas.toView(QPointF(at.x(), at.y()));
        if (QLineF(now, event.viewPos).length() <= constants::kTracedPointPickPx) {
            instruments.clearTracedPoint(body); // the traced point itself: stop tracing it
            return;
        }
    }
    const model::BodyState& state = m_canvas.runner().world().bodies[body].state;
    const Vec2 clicked(event.scenePos.x(), event.scenePos.y());
    instruments.setTracedPoint(body, rotate(Vec2(clicked - state.position), -state.angle));
}

bool TracePointTool::wantsKey(int key, Qt::KeyboardModifiers) const
{
    return key == Qt::Key_Escape && !m_canvas.instruments().tracedPoints().empty();
}

bool TracePointTool::keyPress(QKeyEvent* event)
{
    if (event->key() != Qt::Key_Escape || m_canvas.instruments().tracedPoints().empty())
        return false;
    m_canvas.instruments().clearTracedPoints();
    return true;
}

} // namespace impetus::view
