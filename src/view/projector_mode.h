#pragma once
/// \file projector_mode.h
/// View › Projector Mode (F11): the window as a class sees it on a projector.

#include <QFont>
#include <QObject>
#include <QPalette>
#include <QPointer>
#include <QStatusBar>

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
/// The readouts shrink from kProjectorReadoutScale, in steps of kProjectorReadoutStep, as far as
/// the normal size, when that is what lets every one of them fit across the status bar at its
/// full width (long numbers, a narrow projector), and grow back when there is room again: a
/// readout cut off at its last digit or unit reads wrong from the back of the room.
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

    /// The readouts' size now, × the normal size (1 when projector mode is off).
    double readoutScale() const { return m_readoutScale; }

public slots:
    /// Turns projector mode on or off, and keeps the choice in QSettings.
    void setOn(bool on);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void apply(bool on);
    /// Sets the status bar's font to the largest readout scale at which its readouts fit.
    void fitReadouts();
    void setReadoutScale(double scale);

    QMainWindow& m_window;
    CanvasView& m_canvas;
    QAction* m_action = nullptr;
    bool m_on = false;
    QFont m_normalFont; ///< the window's font before projector mode
    QFont m_normalStatusFont; ///< the status bar's font before projector mode
    QPalette m_normalPalette; ///< the window's palette before projector mode
    bool m_wasFullScreen = false; ///< whether the window was full screen before projector mode
    double m_readoutScale = 1; ///< the status bar's font, × the window's normal font (m_normalFont)
    bool m_fitQueued = false; ///< a fitReadouts() is posted and not yet run
    /// The status bar watched while projector mode is on (the window's, which may go first as the
    /// window is destroyed: never asked of the window then).
    QPointer<QStatusBar> m_status;
};

/// The QSettings key that keeps whether projector mode is on.
inline const char* const kProjectorSettingKey = "view/projectorMode";

} // namespace impetus::view
