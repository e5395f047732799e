#pragma once
/// \file language.h
/// The language of the window and the format of its numbers. Impetus is written in English and
/// ships German and Spanish translations (resources/translations/*.ts, built into the program).
/// The language is the system's unless the user chose one (View › Language, kept in QSettings);
/// numbers in the attribute pane and the readouts follow the same locale ("0,25" in German),
/// while scene files always use a decimal point (model/scene_io.h does not read the locale).

#include <QLocale>
#include <QMenu>
#include <QString>

#include <vector>

class QActionGroup;
class QCoreApplication;
class QMainWindow;

namespace impetus::view {

/// The QSettings key that holds the user's language: a code such as "de", or empty (absent) for
/// the system's language.
inline const char* const kLanguageSettingKey = "language";

/// The languages the app speaks, as codes: "en" (the language it is written in), "de", "es".
std::vector<QString> availableLanguages();

/// The language code kept in QSettings, or an empty string for the system's language. A code that
/// is not in availableLanguages() (a settings file from a newer version) counts as empty.
QString languageSetting();

/// Keeps `code` ("de", …, or empty for the system's language) in QSettings for the next start.
void setLanguageSetting(const QString& code);

/// The locale the window uses: the language the user chose, with the conventions of the country
/// that language is most spoken in, or the system locale when no language was chosen.
/// Either way without group separators, as the attribute pane shows and reads numbers ("1234.5",
/// never "1,234.5", which would read as 1.2345 in German).
QLocale chosenLocale();

/// Makes `locale` the application's: installs its translation of Impetus (and of Qt's own
/// dialogs, when the system has them, Debian package qt6-translations-l10n) on `app`, and makes
/// it QLocale's default, which the pane's fields and the readouts format numbers with. Call it
/// before any window is made: widgets take their texts when they are built. Returns true when a
/// translation was installed, false for English, which needs none, or a language without one.
/// The translators are children of `app`; calling this again replaces them.
bool applyLanguage(QCoreApplication& app, const QLocale& locale);

/// View › Language: "System Language" and one entry per language, each named in that language
/// ("Deutsch"), the current choice checked. Choosing one keeps it in QSettings and emits
/// languageChosen(); it takes effect at the next start, since every widget takes its texts when
/// it is built.
class LanguageMenu : public QMenu {
    Q_OBJECT

public:
    /// The menu, titled "&Language" in the current language.
    explicit LanguageMenu(QWidget* parent = nullptr);

signals:
    /// The user chose `code` (empty: the system's language). `notice` says, in the current
    /// language, when the change takes effect, for the status bar.
    void languageChosen(const QString& code, const QString& notice);

private:
    QActionGroup* m_group = nullptr;
};

/// Adds a LanguageMenu to `window`'s View menu (object name "viewMenu"), whose notice goes to the
/// window's status bar.
void addLanguageMenu(QMainWindow& window);

} // namespace impetus::view
