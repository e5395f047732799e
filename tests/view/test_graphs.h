#pragma once
/// \file test_graphs.h
/// Reading what a graph exports, for the view tests.

#include "view/graph_panel.h"

#include <QFile>
#include <QStringList>
#include <QTemporaryDir>

namespace impetus::view::test {

/// The rows of the CSV `graph` exports (GraphPanel::exportCsv into a temporary folder), the header
/// first; empty when the export or the reading fails.
inline QStringList exportedCsvRows(const GraphPanel& graph)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("graph.csv"));
    if (!dir.isValid() || graph.exportCsv(path))
        return {};
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    return QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

} // namespace impetus::view::test
