#pragma once
/// \file test_settings.h
/// Keeps a test's QSettings (recent files, dock layout) in a temporary folder, so that tests never
/// read or change the user's own settings.

#include <QCoreApplication>
#include <QSettings>
#include <QTemporaryDir>

namespace impetus::view::test {

/// While alive, QSettings read and write under a fresh temporary folder, as an application of its
/// own ("impetus-tests").
class TemporarySettings {
public:
    TemporarySettings()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("impetus-tests"));
        QCoreApplication::setApplicationName(QStringLiteral("impetus-tests"));
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_dir.path());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
    }

    /// The folder the settings are written to.
    QString path() const { return m_dir.path(); }

private:
    QTemporaryDir m_dir;
};

} // namespace impetus::view::test
