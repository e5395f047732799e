#include "view/projector_mode.h"

#include "view/canvas_look.h"
#include "view/canvas_view.h"
#include "view/projector_constants.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>

#include <cmath>

namespace impetus::view {

namespace {

/// `font`, `factor` times larger. A font may be sized in points or in pixels (pointSizeF() is
/// then −1); either is scaled.
QFont scaled(QFont font, double factor)
{
    if (font.pointSizeF() > 0)
        font.setPointSizeF(font.pointSizeF() * factor);
    else
        font.setPixelSize(static_cast<int>(std::lround(font.pixelSize() * factor)));
    return font;
}

QPalette projectorPalette()
{
    QPalette palette;
    for (const QPalette::ColorRole role : {QPalette::Window, QPalette::Base, QPalette::AlternateBase, QPalette::ToolTipBase})
        palette.setColor(role, constants::kProjectorWindowColor);
    for (const QPalette::ColorRole role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText, QPalette::ToolTipText})
        palette.setColor(role, constants::kProjectorTextColor);
    palette.setColor(QPalette::Button, constants::kProjectorButtonColor);
    palette.setColor(QPalette::Highlight, constants::kProjectorHighlightColor);
    palette.setColor(QPalette::HighlightedText, constants::kProjectorWindowColor);
    return palette;
}

} // namespace

ProjectorMode::ProjectorMode(QMainWindow& window, CanvasView& canvas)
    : QObject(&window)
    , m_window(window)
    , m_canvas(canvas)
    , m_action(new QAction(tr("&Projector Mode"), &window))
{
    m_action->setObjectName(QStringLiteral("projectorModeAction"));
    m_action->setCheckable(true);
    m_action->setShortcut(QKeySequence(Qt::Key_F11));
    m_action->setStatusTip(tr("Full screen, large text and readouts, thick lines and strong contrast for a "
                              "projector (F11)"));
    m_window.addAction(m_action);
    if (auto* viewMenu = m_window.findChild<QMenu*>(QStringLiteral("viewMenu"))) {
        viewMenu->addSeparator();
        viewMenu->addAction(m_action);
    }
    connect(m_action, &QAction::toggled, this, &ProjectorMode::setOn);
    if (QSettings().value(QLatin1String(kProjectorSettingKey), false).toBool())
        m_action->setChecked(true);
}

void ProjectorMode::setOn(bool on)
{
    if (on == m_on)
        return;
    m_on = on;
    m_action->setChecked(on);
    apply(on);
    QSettings().setValue(QLatin1String(kProjectorSettingKey), on);
}

void ProjectorMode::apply(bool on)
{
    QStatusBar* status = m_window.statusBar();
    // The menus are windows of their own, which take no font or palette from the main window.
    const QList<QMenu*> menus = m_window.menuBar()->findChildren<QMenu*>();
    if (on) {
        m_normalFont = m_window.font();
        m_normalStatusFont = status->font();
        m_normalPalette = m_window.palette();
        m_wasFullScreen = m_window.isFullScreen();
        const QFont large = scaled(m_normalFont, constants::kProjectorFontScale);
        const QPalette palette = projectorPalette();
        m_window.setFont(large);
        m_window.setPalette(palette);
        for (QMenu* menu : menus) {
            menu->setFont(large);
            menu->setPalette(palette);
        }
        status->setFont(scaled(m_normalFont, constants::kProjectorReadoutScale));
        m_canvas.setLook(CanvasLook::projector());
        if (!m_wasFullScreen)
            m_window.setWindowState(m_window.windowState() | Qt::WindowFullScreen);
    } else {
        m_window.setFont(m_normalFont);
        m_window.setPalette(m_normalPalette);
        // A default QFont and QPalette set nothing: the menus go back to the application's.
        for (QMenu* menu : menus) {
            menu->setFont(QFont());
            menu->setPalette(QPalette());
        }
        status->setFont(m_normalStatusFont);
        m_canvas.setLook(CanvasLook{});
        if (!m_wasFullScreen)
            m_window.setWindowState(m_window.windowState() & ~Qt::WindowFullScreen);
    }
}

} // namespace impetus::view
