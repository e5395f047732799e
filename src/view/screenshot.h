#pragma once
/// \file screenshot.h
/// Rendering the canvas to an image, for `impetus --screenshot` and for handouts.

#include <QImage>
#include <QSize>

namespace impetus::view {

class CanvasView;

/// Renders `canvas` as a user would see it in a canvas of `size` pixels: the canvas is resized to
/// `size`, laid out without ever appearing on screen, framed to its frameRect() (the bodies as they
/// were when the world was set, as in the window), and painted into an image of exactly `size`
/// (device pixel ratio 1, whatever the screen). Meant for a canvas of its own, not the window's.
/// Needs a QApplication; works with QT_QPA_PLATFORM=offscreen. A null image for an empty size.
QImage renderCanvasImage(CanvasView& canvas, QSize size);

} // namespace impetus::view
