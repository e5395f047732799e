#include "view/screenshot.h"

#include "view/canvas_view.h"

namespace impetus::view {

QImage renderCanvasImage(CanvasView& canvas, QSize size)
{
    if (size.isEmpty())
        return {};
    canvas.resize(size);
    // Polished and laid out like a shown window, but never put on a screen: the viewport gets its
    // final size before the canvas frames the world.
    canvas.setAttribute(Qt::WA_DontShowOnScreen);
    canvas.show();
    canvas.frameWorld();

    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(1);
    image.fill(Qt::white);
    // QWidget::render, not QGraphicsView::render: the whole widget as painted on screen.
    canvas.QWidget::render(&image);
    return image;
}

} // namespace impetus::view
