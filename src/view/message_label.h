#pragma once
/// \file message_label.h
/// The dark-red label in which the attribute pane and the lesson editor say why something was
/// refused or is out of range.

#include <QColor>
#include <QLabel>
#include <QPalette>
#include <QString>

namespace impetus::view {

/// Colour of refusal messages: a dark red (#b91c1c) that reads as an error and keeps a contrast
/// above 4.5:1 on a light window background.
inline const QColor kMessageColor{0xb9, 0x1c, 0x1c};

/// A hidden, word-wrapped plain-text label in kMessageColor, named for tests and screen readers.
inline QLabel* makeMessageLabel(const QString& objectName, const QString& accessibleName, QWidget* parent = nullptr)
{
    auto* label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setAccessibleName(accessibleName);
    label->setWordWrap(true);
    label->setTextFormat(Qt::PlainText);
    QPalette palette = label->palette();
    palette.setColor(QPalette::WindowText, kMessageColor);
    label->setPalette(palette);
    label->hide();
    return label;
}

} // namespace impetus::view
