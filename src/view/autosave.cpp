#include "view/autosave.h"

#include "model/scene_io.h"
#include "view/scene_document.h"
#include "view/scene_loading.h"
#include "view/simulation_runner.h"
#include "view/view_constants.h"

#include <QAbstractButton>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QStandardPaths>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace impetus::view {

namespace {

// File names: <id>.json is the scene, <id>.info its description, <id>.lock the owner's lock.
const QString kSceneSuffix = QStringLiteral(".json");
const QString kInfoSuffix = QStringLiteral(".info");
const QString kLockSuffix = QStringLiteral(".lock");
const QString kUnreadableFolder = QStringLiteral("unreadable");

// Keys of the .info file.
const QString kOriginalFileKey = QStringLiteral("file");
const QString kNameKey = QStringLiteral("name");
const QString kSavedAtKey = QStringLiteral("savedAt");

/// The environment variable that shortens the interval, s.
constexpr char kIntervalVariable[] = "IMPETUS_AUTOSAVE_INTERVAL";

std::filesystem::path nativePath(const QString& path)
{
    return std::filesystem::path(QFile::encodeName(path).toStdString());
}

/// A lock that only a dead owner gives up. QLockFile's default also takes a lock older than 30 s
/// from a live owner; an autosave's owner holds its lock for as long as the window is open.
std::shared_ptr<QLockFile> makeLock(const QString& path)
{
    auto lock = std::make_shared<QLockFile>(path);
    lock->setStaleLockTime(0);
    return lock;
}

QString formatProblems(const QStringList& problems) { return problems.join(QLatin1Char('\n')); }

} // namespace

Autosave::Autosave(SceneDocument& document, const QString& folder, std::chrono::milliseconds interval,
                   QObject* parent)
    : QObject(parent),
      m_document(document),
      m_folder(folder),
      // The process id alone could come back after a reboot; with the start time it cannot.
      m_id(QStringLiteral("autosave-%1-%2")
               .arg(QCoreApplication::applicationPid())
               .arg(QDateTime::currentMSecsSinceEpoch())),
      m_lock(QDir(folder).filePath(m_id + kLockSuffix))
{
    QDir().mkpath(m_folder);
    m_lock.setStaleLockTime(0);
    // Without the lock another Impetus would take this autosave for an orphan; saving still works,
    // so a folder where locks fail (a read-only one) only costs the recovery, not the window.
    m_lock.tryLock(0);
    m_timer.setInterval(interval);
    connect(&m_timer, &QTimer::timeout, this, &Autosave::saveNow);
    m_timer.start();
    // SceneDocument pushes the run's command when the run starts (it connected first), so the
    // document is already modified here and the autosave holds the world at Play.
    connect(&document.runner(), &SimulationRunner::runningChanged, this, [this](bool running) {
        if (running)
            saveNow();
    });
}

Autosave::~Autosave()
{
    QFile::remove(scenePath());
    QFile::remove(infoPath());
}

QString Autosave::defaultFolder()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(QStringLiteral("autosave"));
}

std::chrono::milliseconds Autosave::intervalFromEnvironment()
{
    bool ok = false;
    const double seconds = qEnvironmentVariable(kIntervalVariable).toDouble(&ok);
    if (ok && seconds > 0 && seconds * 1000 < std::numeric_limits<int>::max())
        return std::chrono::milliseconds(std::max<long long>(1, std::llround(seconds * 1000)));
    return std::chrono::milliseconds(constants::kAutosaveIntervalMs);
}

QString Autosave::scenePath() const { return QDir(m_folder).filePath(m_id + kSceneSuffix); }

QString Autosave::infoPath() const { return QDir(m_folder).filePath(m_id + kInfoSuffix); }

bool Autosave::saveNow()
{
    if (!m_document.isModified()) {
        QFile::remove(scenePath());
        QFile::remove(infoPath());
        m_lastError.clear();
        return true;
    }
    // The description first: a kill between the two writes leaves a description without a scene
    // (nothing to offer, removed at the next start) rather than a scene nobody can name.
    QJsonObject info;
    info[kOriginalFileKey] = m_document.filePath();
    info[kNameKey] = m_document.displayName();
    info[kSavedAtKey] = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
    QSaveFile infoFile(infoPath());
    if (!infoFile.open(QIODevice::WriteOnly) || infoFile.write(QJsonDocument(info).toJson()) < 0
        || !infoFile.commit()) {
        m_lastError = tr("cannot write the autosave '%1': %2").arg(infoPath(), infoFile.errorString());
        return false;
    }
    if (const std::optional<std::string> error = model::saveSceneFile(nativePath(scenePath()), m_document.worldToSave())) {
        m_lastError = QString::fromStdString(*error);
        return false;
    }
    m_lastError.clear();
    return true;
}

std::vector<OrphanedAutosave> Autosave::findOrphans() const
{
    std::vector<OrphanedAutosave> orphans;
    const QDir dir(m_folder);
    QStringList ids;
    for (const QString& name : dir.entryList({QStringLiteral("*") + kSceneSuffix, QStringLiteral("*") + kInfoSuffix},
                                             QDir::Files, QDir::Name)) {
        const QString id = QFileInfo(name).completeBaseName();
        if (id != m_id && !ids.contains(id))
            ids.push_back(id);
    }
    for (const QString& id : ids) {
        OrphanedAutosave orphan;
        orphan.scenePath = dir.filePath(id + kSceneSuffix);
        orphan.infoPath = dir.filePath(id + kInfoSuffix);
        orphan.lock = makeLock(dir.filePath(id + kLockSuffix));
        // A live owner holds the lock: its autosave is its own business.
        if (!orphan.lock->tryLock(0))
            continue;
        if (!QFileInfo::exists(orphan.scenePath)) {
            // Killed before its first scene was written: there is nothing to restore.
            remove(orphan);
            continue;
        }
        QFile infoFile(orphan.infoPath);
        QJsonParseError parseError;
        const QJsonDocument info = infoFile.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(infoFile.readAll(), &parseError)
                                                                      : QJsonDocument();
        if (!info.isObject()) {
            orphan.problems.push_back(infoFile.isOpen() ? tr("%1: not a description of an autosave: %2")
                                                              .arg(orphan.infoPath, parseError.errorString())
                                                        : tr("%1: cannot read it: %2").arg(orphan.infoPath, infoFile.errorString()));
        } else {
            const QJsonObject object = info.object();
            orphan.originalFile = object.value(kOriginalFileKey).toString();
            orphan.displayName = object.value(kNameKey).toString();
            orphan.savedAt = QDateTime::fromString(object.value(kSavedAtKey).toString(), Qt::ISODateWithMs);
        }
        model::SceneLoadResult scene = loadScene(orphan.scenePath);
        if (scene.ok()) {
            orphan.world = std::move(scene.world);
        } else {
            for (const QString& problem : problemMessages(scene))
                orphan.problems.push_back(orphan.scenePath + QStringLiteral(": ") + problem);
        }
        if (!orphan.savedAt.isValid())
            orphan.savedAt = QFileInfo(orphan.scenePath).lastModified().toUTC();
        orphans.push_back(std::move(orphan));
    }
    std::stable_sort(orphans.begin(), orphans.end(),
                     [](const OrphanedAutosave& a, const OrphanedAutosave& b) { return a.savedAt > b.savedAt; });
    return orphans;
}

QString Autosave::keepAside(const OrphanedAutosave& orphan) const
{
    const QDir dir(m_folder);
    dir.mkpath(kUnreadableFolder);
    const QDir aside(dir.filePath(kUnreadableFolder));
    for (const QString& path : {orphan.scenePath, orphan.infoPath}) {
        if (QFileInfo::exists(path))
            QFile::rename(path, aside.filePath(QFileInfo(path).fileName()));
    }
    // Whatever could not be moved is removed, so that it is not offered again at every start.
    remove(orphan);
    return aside.path();
}

void Autosave::remove(const OrphanedAutosave& orphan)
{
    QFile::remove(orphan.scenePath);
    QFile::remove(orphan.infoPath);
    if (orphan.lock)
        orphan.lock->unlock();
}

std::optional<QStringList> Autosave::restore(const OrphanedAutosave& orphan)
{
    if (!orphan.problems.isEmpty() || !orphan.world)
        return orphan.problems;
    const QString name = orphan.displayName.isEmpty() ? QFileInfo(orphan.originalFile).completeBaseName()
                                                      : orphan.displayName;
    m_document.setScene(*orphan.world, orphan.originalFile, name);
    // The restored work is not in any file yet: the document is modified until it is saved.
    m_document.undoStack()->resetClean();
    // Written under this process before the orphan goes, so that the work is never only in memory.
    saveNow();
    remove(orphan);
    return std::nullopt;
}

bool offerRecovery(QWidget* parent, Autosave& autosave)
{
    for (const OrphanedAutosave& orphan : autosave.findOrphans()) {
        const QString when = QLocale().toString(orphan.savedAt.toLocalTime(), QLocale::LongFormat);
        if (!orphan.problems.isEmpty()) {
            const QString folder = autosave.keepAside(orphan);
            QMessageBox box(QMessageBox::Warning, Autosave::tr("Restore Unsaved Work"),
                            Autosave::tr("An autosave from %1 cannot be read and was not restored. It was kept in "
                                         "“%2”.")
                                .arg(when, folder),
                            QMessageBox::Ok, parent);
            box.setObjectName(QStringLiteral("unreadableAutosaveBox"));
            box.setDetailedText(formatProblems(orphan.problems));
            box.setInformativeText(orphan.problems.value(0));
            box.exec();
            continue;
        }
        const QString sceneName = orphan.originalFile.isEmpty() ? orphan.displayName
                                                                : QFileInfo(orphan.originalFile).fileName();
        QMessageBox box(QMessageBox::Question, Autosave::tr("Restore Unsaved Work"),
                        Autosave::tr("Impetus was not closed properly. Your work on “%1” was saved "
                                     "automatically at %2.")
                            .arg(sceneName, when),
                        QMessageBox::NoButton, parent);
        box.setObjectName(QStringLiteral("recoverAutosaveBox"));
        box.setInformativeText(Autosave::tr("Restore it? Discarding deletes the autosave."));
        QPushButton* restoreButton = box.addButton(Autosave::tr("Restore"), QMessageBox::AcceptRole);
        restoreButton->setObjectName(QStringLiteral("restoreAutosaveButton"));
        QPushButton* discardButton = box.addButton(QMessageBox::Discard);
        discardButton->setObjectName(QStringLiteral("discardAutosaveButton"));
        box.setDefaultButton(restoreButton);
        box.exec();
        if (box.clickedButton() == discardButton) {
            Autosave::remove(orphan);
            continue;
        }
        if (box.clickedButton() != restoreButton) {
            // Closed without an answer: nothing is lost, the autosave is offered again next time.
            orphan.lock->unlock();
            continue;
        }
        if (const std::optional<QStringList> problems = autosave.restore(orphan)) {
            QMessageBox::warning(parent, Autosave::tr("Restore Unsaved Work"), formatProblems(*problems));
            continue;
        }
        return true;
    }
    return false;
}

} // namespace impetus::view
