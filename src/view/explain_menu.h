#pragma once
/// \file explain_menu.h
/// The Explain menu: Separating Axes and the Collision Inspector (docs/explainers.md).

namespace impetus::view {

class MainWindow;

/// Adds the Explain menu to `window`: Explain › Separating Axes (enabled while exactly two bodies
/// are selected; object name "separatingAxesAction") opens a SatExplainer (object name
/// "satExplainer") on the canvas, and Explain › Collision Inspector ("collisionInspectorAction")
/// shows or hides the dock "collisionInspectorDock" holding a CollisionInspector.
void addExplainers(MainWindow& window);

} // namespace impetus::view
