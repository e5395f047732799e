#pragma once
/// \file projector_mode.h
/// View › Projector Mode (F11): the window as a class sees it on a projector.

#include <QFont>
#include <QObject>
#include <QPalette>

class QAction;
class QMainWindow;

namespace impetus::view {

class CanvasView;

/// Projector mode of a main window. On, the window goes full screen; its text is
/// constants::kProjectorFontScale times larger and the status bar's readouts
/// kProjectorReadoutScale times; its palette is black on white with a dark blue highlight; and the
/// canvas draws with CanvasLook::projector() (thick lines, dark outlines and grid, colliding
/// bodies hatched besides red). Off, everything is as before. The choice is kept in QSettings
/// (key kProjectorSettingKey) and restored when the next window is made.
///
/// The object adds its checkable action (object name "projectorModeAction", shortcut F11) to the
/// window's View menu (object name "viewMenu") and to the window itself, so that F11 works
/// wherever the focus is.
class ProjectorMode : public QObject {
    Q_OBJECT

public:
    /// Projector mode for `window`, whose canvas is `canvas`; both must outlive it (it is a child
    /// of the window). Turns it on at once when QSettings says it was on when last left.
    ProjectorMode(QMainWindow& window, CanvasView& canvas);

    /// The View › Projector Mode action.
    QAction* action() const { return m_action; }

    /// Whether projector mode is on.
    bool isOn() const { return m_on; }

public slots:
    /// Turns projector mode on or off, and keeps the choice in QSettings.
    void setOn(bool on);

private:
    void apply(bool on);

    QMainWindow& m_window;
    CanvasView& m_canvas;
    QAction* m_action = nullptr;
    bool m_on = false;
    QFont m_normalFont; ///< the window's font before projector mode
    QFont m_normalStatusFont; ///< the status bar's font before projector mode
    QPalette m_normalPalette; ///< the window's palette before projector mode
    bool m_wasFullScreen = false; ///< whether the window was full screen before projector mode
};

/// The QSettings key that keeps whether projector mode is on.
inline const char* const kProjectorSettingKey = "view/projectorMode";

} // namespace impetus::view
