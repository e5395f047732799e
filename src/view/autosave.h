#pragma once
/// \file autosave.h
/// Autosave and recovery: the open scene is written to the app-data folder every minute and at
/// every run start, so that a crash or a kill loses at most a minute of work; the next start
/// offers to restore it. docs/app.md, "Autosave and recovery".

#include "model/world.h"

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <chrono>
#include <memory>
#include <optional>
#include <vector>

class QWidget;

namespace impetus::view {

class SceneDocument;

/// An autosave that an Impetus left behind without quitting cleanly (its process is gone).
struct OrphanedAutosave {
    QString scenePath; ///< the autosaved scene, an ordinary scene file
    QString infoPath; ///< what the scene was: its file, its name, when it was saved
    QString originalFile; ///< the scene's own file, empty for a new scene or an example
    QString displayName; ///< the scene's name as the title showed it
    QDateTime savedAt; ///< when it was written (UTC); invalid when unknown
    /// Why it cannot be restored, one line each ("path: reason"); empty when it can.
    QStringList problems;
    std::optional<model::World> world; ///< the scene read from scenePath, when it could be
    /// Held from the moment it is found, so that no other Impetus starting now offers it too.
    std::shared_ptr<QLockFile> lock;
};

/// Writes the scene of one SceneDocument to `<folder>/<id>.json` (an ordinary scene file) with
/// `<id>.info` (JSON: the scene's file, its name, the time), while this object holds
/// `<id>.lock`. The id is this process's id and its start time, so two windows or processes
/// never write the same files; the lock says the owner is alive. A scene without changes since it
/// was loaded or saved has no autosave (there is nothing to lose). Destroying the object (a clean
/// quit) removes its files.
class Autosave : public QObject {
    Q_OBJECT

public:
    /// Autosaves `document` into `folder` (created when missing) every `interval`, and whenever a
    /// run starts. The document must outlive this object.
    Autosave(SceneDocument& document, const QString& folder, std::chrono::milliseconds interval,
             QObject* parent = nullptr);
    /// Removes this autosave's files: a clean quit leaves nothing to recover.
    ~Autosave() override;

    /// The platform's folder for autosaves: QStandardPaths::AppDataLocation + "/autosave"
    /// (on Linux ~/.local/share/impetus/impetus/autosave, or under $XDG_DATA_HOME).
    static QString defaultFolder();

    /// The autosave interval: the environment variable IMPETUS_AUTOSAVE_INTERVAL in seconds when
    /// it holds a number > 0 (for tests and demonstrations), else constants::kAutosaveIntervalMs (a minute).
    static std::chrono::milliseconds intervalFromEnvironment();

    /// The folder autosaves go to.
    QString folder() const { return m_folder; }
    /// This process's autosaved scene and its description.
    QString scenePath() const;
    QString infoPath() const;

    /// Writes the autosave now when the document is modified, or removes it when it is not.
    /// False when writing failed (lastError() says why; the last good autosave stays).
    bool saveNow();
    /// Why the last saveNow() failed; empty after a success.
    QString lastError() const { return m_lastError; }

    /// The autosaves in folder() whose owner is gone, newest first, each locked for this process
    /// and read: those that cannot be read carry their problems. Never this object's own.
    std::vector<OrphanedAutosave> findOrphans() const;

    /// Moves an unreadable autosave's files into folder()/unreadable, where they stay for the
    /// user to look at and are never offered again. Returns the folder they went to.
    QString keepAside(const OrphanedAutosave& orphan) const;

    /// Removes an orphan's files (after it was restored or discarded) and releases its lock.
    static void remove(const OrphanedAutosave& orphan);

    /// Restores `orphan` into the document: its scene, under its original file and name, marked
    /// modified so that closing asks to save and Save writes to the original file. Autosaves it at
    /// once under this process and removes the orphan. On failure returns the problems and changes
    /// nothing.
    std::optional<QStringList> restore(const OrphanedAutosave& orphan);

private:
    SceneDocument& m_document;
    QString m_folder;
    QString m_id;
    QLockFile m_lock;
    QTimer m_timer;
    QString m_lastError;
};

/// At start: offers every orphaned autosave in `autosave`'s folder, newest first. An unreadable
/// one gets a message (object name "unreadableAutosaveBox") naming the problem and where it was
/// kept; a readable one a question (object name "recoverAutosaveBox") naming the scene and the
/// time it was saved, with Restore (object name "restoreAutosaveButton") and Discard. Restoring
/// one stops there: the others stay for the next start. Returns true when a scene was restored.
bool offerRecovery(QWidget* parent, Autosave& autosave);

} // namespace impetus::view
