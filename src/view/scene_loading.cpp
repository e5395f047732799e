#include "view/scene_loading.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <filesystem>
#include <string>

namespace impetus::view {

model::SceneLoadResult loadScene(const QString& path)
{
    if (!path.startsWith(QLatin1Char(':'))) {
        // QFile::encodeName gives the bytes the operating system uses for the name.
        const QByteArray native = QFile::encodeName(path);
        return model::loadSceneFile(std::filesystem::path(native.toStdString()));
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        const QString reason = QCoreApplication::translate("impetus::view", "cannot read %1: %2")
                                   .arg(path, file.errorString());
        return model::SceneLoadResult{std::nullopt, {model::SceneProblem{"(file)", reason.toStdString()}}};
    }
    const QByteArray text = file.readAll();
    return model::parseScene(std::string_view(text.constData(), static_cast<std::size_t>(text.size())));
}

QStringList problemMessages(const model::SceneLoadResult& result)
{
    QStringList messages;
    for (const model::SceneProblem& problem : result.problems)
        messages << QString::fromStdString(problem.toString());
    return messages;
}

QString sceneDisplayName(const QString& path) { return QFileInfo(path).completeBaseName(); }

} // namespace impetus::view
