#include "view/language.h"

#include <QActionGroup>
#include <QCoreApplication>
#include <QLibraryInfo>
#include <QMainWindow>
#include <QStatusBar>
#include <QSettings>
#include <QTranslator>

#include <algorithm>

namespace impetus::view {

namespace {

/// Where the build puts the compiled translations (qt_add_translations in src/view/CMakeLists.txt):
/// ":/translations/impetus_de.qm" and so on.
const QString kTranslationsPath = QStringLiteral(":/translations");

/// Object names of the translators applyLanguage() installs, so a second call finds and replaces them.
const QString kAppTranslatorName = QStringLiteral("impetusTranslator");
const QString kQtTranslatorName = QStringLiteral("qtTranslator");

void removeTranslator(QCoreApplication& app, const QString& name)
{
    if (auto* old = app.findChild<QTranslator*>(name, Qt::FindDirectChildrenOnly)) {
        QCoreApplication::removeTranslator(old);
        delete old;
    }
}

/// Loads "<base>_<language>.qm" from `folder` for `locale` and installs it; false when there is none.
bool installTranslator(QCoreApplication& app, const QLocale& locale, const QString& base, const QString& folder,
                       const QString& name)
{
    auto* translator = new QTranslator(&app);
    translator->setObjectName(name);
    if (!translator->load(locale, base, QStringLiteral("_"), folder) || !QCoreApplication::installTranslator(translator)) {
        delete translator;
        return false;
    }
    return true;
}

/// A language the app speaks: its code, and its name for itself ("Deutsch"), so that a user finds
/// theirs whatever the window speaks; for that reason the names are not translated.
/// (QLocale::nativeLanguageName() would name a country's variant: "American English".)
struct Language {
    const char* code;
    const char* name;
};

/// English first: the language Impetus is written in.
constexpr Language kLanguages[] = {{"en", "English"}, {"de", "Deutsch"}, {"es", "Español"}};

} // namespace

std::vector<QString> availableLanguages()
{
    std::vector<QString> codes;
    for (const Language& language : kLanguages)
        codes.push_back(QString::fromLatin1(language.code));
    return codes;
}

QString languageSetting()
{
    const QString code = QSettings().value(QLatin1String(kLanguageSettingKey)).toString();
    const std::vector<QString> known = availableLanguages();
    return std::find(known.begin(), known.end(), code) != known.end() ? code : QString();
}

void setLanguageSetting(const QString& code)
{
    QSettings settings;
    if (code.isEmpty())
        settings.remove(QLatin1String(kLanguageSettingKey));
    else
        settings.setValue(QLatin1String(kLanguageSettingKey), code);
}

QLocale chosenLocale()
{
    const QString code = languageSetting();
    // QLocale("de") is German as in Germany: the country most speakers of the language live in.
    QLocale locale = code.isEmpty() ? QLocale::system() : QLocale(code);
    locale.setNumberOptions(QLocale::OmitGroupSeparator | QLocale::RejectGroupSeparator);
    return locale;
}

bool applyLanguage(QCoreApplication& app, const QLocale& locale)
{
    QLocale::setDefault(locale);
    removeTranslator(app, kAppTranslatorName);
    removeTranslator(app, kQtTranslatorName);
    if (locale.language() == QLocale::English || locale.language() == QLocale::C)
        return false;
    // Qt's own strings (the buttons of standard dialogs) come from the system, when installed;
    // without them those few buttons stay in English.
    installTranslator(app, locale, QStringLiteral("qtbase"), QLibraryInfo::path(QLibraryInfo::TranslationsPath),
                      kQtTranslatorName);
    return installTranslator(app, locale, QStringLiteral("impetus"), kTranslationsPath, kAppTranslatorName);
}

LanguageMenu::LanguageMenu(QWidget* parent)
    : QMenu(tr("&Language"), parent)
    , m_group(new QActionGroup(this))
{
    setObjectName(QStringLiteral("languageMenu"));
    m_group->setExclusive(true);
    const QString current = languageSetting();
    const auto add = [this, &current](const QString& text, const QString& code) {
        QAction* action = addAction(text);
        action->setCheckable(true);
        action->setChecked(code == current);
        action->setData(code);
        m_group->addAction(action);
        connect(action, &QAction::triggered, this, [this, code] {
            setLanguageSetting(code);
            emit languageChosen(code, tr("The language changes the next time Impetus starts."));
        });
    };
    add(tr("System Language"), QString());
    addSeparator();
    for (const Language& language : kLanguages)
        add(QString::fromUtf8(language.name), QString::fromLatin1(language.code));
}

void addLanguageMenu(QMainWindow& window)
{
    auto* viewMenu = window.findChild<QMenu*>(QStringLiteral("viewMenu"));
    if (!viewMenu)
        return;
    auto* menu = new LanguageMenu(viewMenu);
    viewMenu->addMenu(menu);
    QStatusBar* status = window.statusBar();
    QObject::connect(menu, &LanguageMenu::languageChosen, status,
                     [status](const QString&, const QString& notice) { status->showMessage(notice); });
}

} // namespace impetus::view
