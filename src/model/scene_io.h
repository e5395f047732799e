#pragma once
/// \file scene_io.h
/// Reading and writing scene files, format "impetus-scene" version 1 (see docs/scene-format.md
/// and the public contract). Reading validates every rule and reports every problem at once.

#include "model/world.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impetus::model {

/// The scene-file version this build reads and writes.
inline constexpr int kSceneFormatVersion = 1;

/// The value of the scene key `format`.
inline constexpr std::string_view kSceneFormatName = "impetus-scene";

/// The largest scene file read, bytes (64 MiB). A pretty-printed body takes about 400 bytes, so
/// this holds some 150,000 bodies, far beyond a lesson's scene; the parsed document takes about
/// ten times the file's size in memory, so the cap also bounds what a stray file can cost (a
/// device such as /dev/zero, or a log file opened by mistake). docs/scene-format.md, "Limits".
inline constexpr std::uintmax_t kMaxSceneFileBytes = 64ull * 1024 * 1024;

/// The deepest nesting of JSON arrays and objects read. A scene nests at most 6 deep
/// (root → bodies → body → shape → vertices → [x, y]); deeper input is refused while it is
/// parsed, before it can cost memory or time (a file of ten million '[' would otherwise build a
/// ten-million-level document).
inline constexpr std::size_t kMaxJsonDepth = 64;

/// The most cells a soft body's grid may have: its bounding box's area times its density of
/// ellipses (for "auto", the lowest density it can choose). A million ellipses already take
/// hundreds of megabytes and seconds a step; a density of 1e12 per m², legal as a number, would
/// ask for a grid the lattice's int indices cannot count. docs/scene-format.md, "Limits".
inline constexpr double kMaxSoftGridCells = 1e6;

/// One problem in a scene: the JSON path (e.g. "bodies[2].shape.vertices", or "(root)" for the
/// document itself) and the reason. toString() gives "path: reason".
struct SceneProblem {
    std::string path; ///< where in the document, e.g. "bodies[2].shape.vertices"
    std::string reason; ///< what is wrong there, in words
    std::string toString() const { return path + ": " + reason; } ///< "path: reason"
    bool operator==(const SceneProblem&) const = default; ///< memberwise equality
};

/// The outcome of reading a scene: a complete world, or no world and every problem found.
/// Never a partial world.
struct SceneLoadResult {
    std::optional<World> world; ///< the scene, when it was read without a problem
    std::vector<SceneProblem> problems; ///< every problem found; empty when `world` is present
    bool ok() const { return world.has_value(); } ///< true when the scene was read
};

/// Parses and validates scene JSON text. Nesting deeper than kMaxJsonDepth is refused, and
/// running out of memory gives a problem, never an exception. Every body's derived data is computed (Body::updateDerived),
/// spring rest lengths and joint anchors/lengths are filled in from the load-time poses.
SceneLoadResult parseScene(std::string_view jsonText);

/// Reads a scene file; a file that cannot be read is one problem with path "(file)". Only a
/// regular file (or a link to one) of at most kMaxSceneFileBytes is read: a device, a pipe, a
/// socket or a folder is refused before it is opened, so reading never blocks or runs forever.
/// Running out of memory is a problem too, never an exception.
SceneLoadResult loadSceneFile(const std::filesystem::path& path);

/// The scene as JSON text (2-space indent, trailing newline), every key written explicitly.
/// parseScene(serializeScene(w)) gives a world equal to w (time and step count reset to 0).
std::string serializeScene(const World& world);

/// Writes the scene atomically: to a temporary file in the same folder, then renamed over `path`,
/// so a failure never leaves a half-written or lost file. Returns an error message on failure.
std::optional<std::string> saveSceneFile(const std::filesystem::path& path, const World& world);

} // namespace impetus::model
