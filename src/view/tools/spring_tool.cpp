#include "view/tools/spring_tool.h"

#include "view/scene_document.h"

#include <QLineF>

namespace impetus::view {

void SpringTool::connectEnds(const Attachment& a, const QPointF& from, const Attachment& b, const QPointF& to)
{
    model::Spring spring;
    spring.bodyA = *a.body;
    spring.anchorA = a.anchor;
    spring.bodyB = b.body;
    spring.anchorB = b.anchor;
    // Drawn at rest: a new spring pulls only once something moves.
    spring.restLength = QLineF(from, to).length();
    m_document.addSpring(spring, tr("Add spring"));
}

QString SpringTool::startHint() const
{
    return tr("Drag from a body to another body, or to a point in space, to add a spring.");
}

} // namespace impetus::view
