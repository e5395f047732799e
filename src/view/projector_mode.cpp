#include "view/projector_mode.h"

#include "view/canvas_look.h"
#include "view/canvas_view.h"
#include "view/projector_constants.h"

#include <QAction>
#include <QEvent>
#include <QFontMetricsF>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <vector>

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
        m_status = status;
        setReadoutScale(constants::kProjectorReadoutScale);
        status->installEventFilter(this);
        fitReadouts();
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
        status->removeEventFilter(this);
        m_status = nullptr;
        status->setFont(m_normalStatusFont);
        m_readoutScale = 1;
        m_canvas.setLook(CanvasLook{});
        if (!m_wasFullScreen)
            m_window.setWindowState(m_window.windowState() & ~Qt::WindowFullScreen);
    }
}

bool ProjectorMode::eventFilter(QObject* watched, QEvent* event)
{
    // A readout whose text grows asks its parent, the status bar, for a new layout; a resize
    // changes the room. Either may change what fits: looked at once the events have settled.
    if (m_on && m_status && watched == m_status &&
        (event->type() == QEvent::LayoutRequest || event->type() == QEvent::Resize) && !m_fitQueued) {
        m_fitQueued = true;
        QTimer::singleShot(0, this, [this] {
            m_fitQueued = false;
            fitReadouts();
        });
    }
    return QObject::eventFilter(watched, event);
}

void ProjectorMode::setReadoutScale(double scale)
{
    m_readoutScale = scale;
    if (m_status)
        m_status->setFont(scaled(m_normalFont, scale));
}

void ProjectorMode::fitReadouts()
{
    if (!m_on || !m_status)
        return;
    QStatusBar* status = m_status;
    // A window not yet shown has no width of its own yet: it is fitted when it is shown.
    if (!status->isVisible())
        return;
    const int room = status->width();
    // Each readout's width at a scale: its text in that font, plus what its label adds around the
    // text (margins), which does not grow with the font.
    struct Readout {
        QString text;
        int around = 0;
    };
    std::vector<Readout> readouts;
    const QFontMetricsF now(status->font());
    for (QLabel* label : status->findChildren<QLabel*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (!label->isVisibleTo(status))
            continue;
        const QString text = label->text();
        readouts.push_back({text, label->sizeHint().width() - static_cast<int>(std::ceil(now.horizontalAdvance(text)))});
    }
    if (room <= 0 || readouts.empty())
        return;
    const auto widthAt = [&](double scale) {
        const QFontMetricsF metrics(scaled(m_normalFont, scale));
        double width = constants::kStatusBarEndsPx;
        for (const Readout& readout : readouts)
            width += std::ceil(metrics.horizontalAdvance(readout.text)) + readout.around + constants::kStatusBarSpacingPx;
        return width;
    };
    // As large as fits, from the size now: a step smaller at a time until the readouts fit (down
    // to the normal size), or a step larger when they fit with room to spare. Usually one or two
    // measures, as this runs whenever a readout's text changes width. Counted in whole steps, so
    // that a size left and come back to is the same number.
    const double step = constants::kProjectorReadoutStep;
    const auto scaleOf = [step](int steps) { return 1 + steps * step; };
    const int most = static_cast<int>(std::lround((constants::kProjectorReadoutScale - 1) / step));
    const int current = std::clamp(static_cast<int>(std::lround((m_readoutScale - 1) / step)), 0, most);
    int best = current;
    if (widthAt(scaleOf(best)) > room) {
        while (best > 0 && widthAt(scaleOf(best)) > room)
            --best;
    } else {
        while (best < most && widthAt(scaleOf(best + 1)) <= room * (1 - constants::kProjectorReadoutGrowRoom))
            ++best;
    }
    if (best != current || std::abs(scaleOf(best) - m_readoutScale) > 1e-12)
        setReadoutScale(best == most ? constants::kProjectorReadoutScale : scaleOf(best));
}

} // namespace impetus::view
