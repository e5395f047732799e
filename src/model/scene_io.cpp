#include "model/scene_io.h"

#include "model/lesson_io.h"
#include "model/pin_anchors.h"
#include "model/polygon.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <iomanip>
#include <map>
#include <memory>
#include <new>
#include <random>
#include <span>
#include <sstream>
#include <system_error>
#include <utility>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <unistd.h>
#define IMPETUS_SCENE_IO_POSIX 1
#endif

namespace impetus::model {

namespace {

namespace fs = std::filesystem;

/// The reading side works on nlohmann::json, whose objects are std::maps: lookups stay
/// logarithmic even in a hostile file with a million keys (ordered_json searches linearly).
using Json = nlohmann::json;

/// The writing side keeps keys in the order a person expects to read them.
using OrderedJson = nlohmann::ordered_json;

/// The path of a problem that concerns the document as a whole.
constexpr std::string_view kRootPath = "(root)";

/// The path of a problem that concerns the file rather than its contents.
constexpr std::string_view kFilePath = "(file)";

/// A fixed body with no `color` is drawn in this neutral grey, so that scenery (floors, ramps,
/// walls) reads as background next to the default blue of moving bodies.
constexpr Color kFixedBodyColor{0x7a, 0x7f, 0x87};

/// Indentation of written scenes, in spaces per level.
constexpr std::size_t kIndentWidth = 2;

/// Strings quoted in a message are cut to this many bytes, so that a stray megabyte-long value
/// cannot bury the message that names it.
constexpr std::size_t kMaxQuotedBytes = 40;

/// "did you mean …?" is offered for a name at most this many single-character edits away: enough
/// for a typo or a British spelling ("colour"), not so many that unrelated names are offered.
constexpr std::size_t kMaxSuggestionDistance = 2;

/// Names longer than this are not compared for suggestions; the edit distance is quadratic.
constexpr std::size_t kMaxSuggestionLength = 64;

/// At most this many unknown body names get a "did you mean …?". Each suggestion compares the
/// name with every body; without a budget a generated file with thousands of bad references to
/// thousands of bodies would take minutes, and nobody reads past the first few messages.
constexpr int kMaxBodySuggestions = 32;

/// The deepest object a scene holds sits at this depth (root 0 → bodies[i] 2 → shape 3).
/// Duplicate keys are looked for down to here; anything deeper is refused as a wrong type anyway.
constexpr std::size_t kDeepestSceneObject = 3;

/// How many temporary-file names saveSceneFile tries before giving up; a clash needs another
/// writer to have picked the same 64-bit random name, so more than one retry is already paranoid.
constexpr int kTempNameAttempts = 8;

/// How many problems a refused save lists before "and N more".
constexpr std::size_t kMaxProblemsInSaveMessage = 3;

/// Bytes read from a scene file per call.
constexpr std::size_t kReadChunkBytes = 64 * 1024;

// ------------------------------------------------------------------------------------------------
// Paths and message text

std::string memberPath(const std::string& parent, std::string_view key)
{
    std::string path = parent;
    if (!path.empty())
        path += '.';
    path += key;
    return path;
}

std::string elementPath(const std::string& parent, std::size_t index)
{
    return parent + '[' + std::to_string(index) + ']';
}

std::string displayPath(const std::string& path) { return path.empty() ? std::string(kRootPath) : path; }

/// Cuts `text` to at most kMaxQuotedBytes without splitting a UTF-8 sequence.
std::string_view truncated(std::string_view text, bool& wasCut)
{
    wasCut = text.size() > kMaxQuotedBytes;
    if (!wasCut)
        return text;
    std::size_t end = kMaxQuotedBytes;
    // A byte 10xxxxxx continues a multi-byte character; back up to the byte that starts it.
    constexpr unsigned char kContinuationMask = 0xc0;
    constexpr unsigned char kContinuationBits = 0x80;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & kContinuationMask) == kContinuationBits)
        --end;
    return text.substr(0, end);
}

/// `text` as a JSON string literal without its quotes: control characters escaped and invalid
/// UTF-8 replaced, so a message is always printable and can itself be written as JSON.
std::string escaped(std::string_view text)
{
    const std::string literal =
        Json(std::string(text)).dump(-1, ' ', false, Json::error_handler_t::replace);
    return literal.substr(1, literal.size() - 2);
}

/// A name or key from the file, in single quotes, for "unknown key 'colour'".
std::string singleQuoted(std::string_view text)
{
    bool wasCut = false;
    const std::string_view shown = truncated(text, wasCut);
    return '\'' + escaped(shown) + (wasCut ? "…'" : "'");
}

/// A value as the message shows it after "got": numbers, booleans, null and strings as written,
/// containers by their kind.
std::string describe(const Json& value)
{
    switch (value.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::boolean:
        return value.get<bool>() ? "true" : "false";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
        return value.dump();
    case Json::value_t::number_float: {
        const double x = value.get<double>();
        if (std::isnan(x))
            return "NaN";
        if (std::isinf(x))
            return x > 0 ? "infinity" : "-infinity";
        return value.dump();
    }
    case Json::value_t::string: {
        bool wasCut = false;
        const std::string_view shown = truncated(value.get_ref<const std::string&>(), wasCut);
        return '"' + escaped(shown) + (wasCut ? "…\"" : "\"");
    }
    case Json::value_t::array:
        if (value.empty())
            return "an empty array";
        return "an array of " + std::to_string(value.size()) + (value.size() == 1 ? " value" : " values");
    case Json::value_t::object:
        return "an object";
    case Json::value_t::binary:
    case Json::value_t::discarded:
        break;
    }
    return "an unsupported value";
}

std::string joined(std::span<const std::string_view> names)
{
    std::string out;
    for (const std::string_view name : names) {
        if (!out.empty())
            out += ", ";
        out += name;
    }
    return out;
}

char lowerAscii(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

/// Levenshtein distance, ignoring ASCII case ("Radius" is one typo from nothing).
std::size_t editDistance(std::string_view a, std::string_view b)
{
    std::vector<std::size_t> previous(b.size() + 1);
    std::vector<std::size_t> current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = lowerAscii(a[i - 1]) == lowerAscii(b[j - 1]) ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

/// The closest of `candidates` to `name`, when it is close enough to be a likely typo.
template <typename Range>
std::optional<std::string> nearestName(std::string_view name, const Range& candidates)
{
    if (name.size() > kMaxSuggestionLength)
        return std::nullopt;
    std::optional<std::string> best;
    std::size_t bestDistance = kMaxSuggestionDistance + 1;
    for (const auto& candidate : candidates) {
        const std::string_view c = candidate;
        const std::size_t lengthGap = c.size() > name.size() ? c.size() - name.size() : name.size() - c.size();
        if (c.size() > kMaxSuggestionLength || lengthGap >= bestDistance)
            continue;
        const std::size_t distance = editDistance(name, c);
        // A distance as large as the name itself means nothing was kept: "x" is not a typo of "y".
        if (distance < bestDistance && distance < std::max(name.size(), c.size())) {
            bestDistance = distance;
            best = std::string(c);
        }
    }
    return best;
}

std::string didYouMean(const std::optional<std::string>& suggestion)
{
    return suggestion ? " (did you mean " + singleQuoted(*suggestion) + "?)" : std::string();
}

/// Line and column (both 1-based, the column in bytes) of the byte at which parsing stopped.
std::pair<std::size_t, std::size_t> lineAndColumn(std::string_view text, std::size_t bytesRead)
{
    // nlohmann reports how many bytes it had read, the offending one included (the end of the
    // input counts as one), so the offending byte is the one at index bytesRead − 1.
    const std::size_t index = std::min(bytesRead == 0 ? 0 : bytesRead - 1, text.size());
    const std::string_view before = text.substr(0, index);
    const auto newlines = static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
    const std::size_t lastNewline = before.rfind('\n');
    const std::size_t column = lastNewline == std::string_view::npos ? index + 1 : index - lastNewline;
    return {newlines + 1, column};
}

/// The reason part of a nlohmann parse error. Its what() reads
/// "[json.exception.parse_error.101] parse error at line 3, column 7: syntax error …"; the
/// position is recomputed by lineAndColumn, so only the text after it is kept.
std::string parseErrorDetail(const std::string& what)
{
    std::string_view detail = what;
    if (const std::size_t bracket = detail.find("] "); bracket != std::string_view::npos)
        detail.remove_prefix(bracket + 2);
    if (detail.starts_with("parse error")) {
        if (const std::size_t colon = detail.find(": "); colon != std::string_view::npos)
            detail.remove_prefix(colon + 2);
    }
    // The detail quotes the bytes last read, which may be invalid UTF-8 or control characters.
    return escaped(detail);
}

// ------------------------------------------------------------------------------------------------
// Freeing a document without allocating

/// Empties `value` from the leaves up without allocating. nlohmann's own destructor flattens a
/// container onto a heap-allocated stack first, so destroying a large document while memory has
/// run out throws from a destructor, and the program aborts instead of reporting the problem.
/// Popping the last child of each container, once the child is itself empty, frees the same
/// memory with no allocation. The recursion is as deep as the document, at most kMaxJsonDepth.
void dismantle(Json& value) noexcept
{
    if (auto* array = value.get_ptr<Json::array_t*>()) {
        while (!array->empty()) {
            dismantle(array->back());
            array->pop_back();
        }
    } else if (auto* object = value.get_ptr<Json::object_t*>()) {
        while (!object->empty()) {
            const auto last = std::prev(object->end());
            dismantle(last->second);
            object->erase(last);
        }
    }
}

/// A parsed document that is freed by dismantle(), also when an exception (out of memory)
/// unwinds past it.
class Document {
public:
    Document() = default;
    explicit Document(Json value) : m_value(std::move(value)) {}
    ~Document() { dismantle(m_value); }
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;

    Json& get() { return m_value; }
    const Json& get() const { return m_value; }

private:
    Json m_value;
};

/// The message for running out of memory while reading `bytes` bytes of scene.
std::string outOfMemoryReason(std::size_t bytes)
{
    return "out of memory while reading the scene (" + std::to_string(bytes) +
           " bytes of JSON): the scene is too large for the memory available";
}

// ------------------------------------------------------------------------------------------------
// Parsing: a SAX handler that builds the document and knows where it is, so that problems the
// parser itself finds (numbers too large for a double, repeated keys) get a real JSON path.

class DocumentBuilder final : public Json::json_sax_t {
public:
    DocumentBuilder(std::string_view text, std::vector<SceneProblem>& problems)
        : m_text(text), m_problems(problems)
    {
    }

    Json takeDocument() { return std::move(m_document.get()); }

    bool null() override { return addValue(Json(nullptr)) != nullptr; }
    bool boolean(bool value) override { return addValue(Json(value)) != nullptr; }
    bool number_integer(number_integer_t value) override { return addValue(Json(value)) != nullptr; }
    bool number_unsigned(number_unsigned_t value) override { return addValue(Json(value)) != nullptr; }
    bool number_float(number_float_t value, const string_t&) override
    {
        return addValue(Json(value)) != nullptr;
    }
    bool string(string_t& value) override { return addValue(Json(std::move(value))) != nullptr; }
    bool binary(binary_t& value) override { return addValue(Json::binary(std::move(value))) != nullptr; }

    bool start_object(std::size_t) override { return open(Json::object()); }
    bool start_array(std::size_t) override { return open(Json::array()); }

    bool key(string_t& name) override
    {
        Frame& top = m_frames.back();
        if (m_frames.size() <= kDeepestSceneObject + 1 && top.value->contains(name))
            m_problems.push_back({displayPath(containerPath()), "duplicate key " + singleQuoted(name)});
        top.key = std::move(name);
        return true;
    }

    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t bytesRead, const std::string& lastToken,
                     const Json::exception& error) override
    {
        // 406: a number that overflows a double (1e999). The parser refuses it before any value
        // exists, so this is the one place that still knows which key it belonged to.
        constexpr int kNumberOverflow = 406;
        if (error.id == kNumberOverflow) {
            m_problems.push_back({displayPath(pendingValuePath()),
                                  "number " + escaped(lastToken) + " is out of range (too large for a double)"});
        } else {
            const auto [line, column] = lineAndColumn(m_text, bytesRead);
            m_problems.push_back({std::string(kRootPath), "invalid JSON at line " + std::to_string(line) +
                                                              ", column " + std::to_string(column) + ": " +
                                                              parseErrorDetail(error.what())});
        }
        return false;
    }

private:
    /// An open object or array: where it lives, how it hangs from its parent (".key" or "[i]"),
    /// the key whose value comes next (objects) or how many elements it has (arrays).
    struct Frame {
        Json* value = nullptr;
        std::string segment;
        std::string key;
        std::size_t count = 0;
    };

    /// Stores `value` where the parser is (root, next array element or current key) and
    /// returns where it now lives. Pointers stay valid: a container only grows while it is the
    /// innermost open one, and then none of its children is open.
    Json* addValue(Json value)
    {
        if (m_frames.empty()) {
            m_document.get() = std::move(value);
            return &m_document.get();
        }
        Frame& top = m_frames.back();
        if (top.value->is_array()) {
            top.value->push_back(std::move(value));
            ++top.count;
            return &top.value->back();
        }
        Json& slot = (*top.value)[top.key];
        slot = std::move(value);
        return &slot;
    }

    bool open(Json container)
    {
        if (m_frames.size() >= kMaxJsonDepth) {
            // Stopping here keeps a hostile file (ten million '[') from costing a document level
            // per byte; the path shown is the one where the limit was crossed.
            m_problems.push_back({displayPath(pendingValuePath()),
                                  "nested deeper than " + std::to_string(kMaxJsonDepth) +
                                      " levels of arrays and objects (a scene needs 6)"});
            return false;
        }
        std::string segment = pendingSegment();
        Json* where = addValue(std::move(container));
        m_frames.push_back(Frame{where, std::move(segment), {}, 0});
        return true;
    }

    bool close()
    {
        m_frames.pop_back();
        return true;
    }

    /// How the value about to be parsed hangs from the innermost open container.
    std::string pendingSegment() const
    {
        if (m_frames.empty())
            return {};
        const Frame& top = m_frames.back();
        if (top.value->is_array())
            return '[' + std::to_string(top.count) + ']';
        return '.' + top.key;
    }

    std::string containerPath() const
    {
        std::string path;
        for (const Frame& frame : m_frames)
            path += frame.segment;
        if (!path.empty() && path.front() == '.')
            path.erase(0, 1);
        return path;
    }

    std::string pendingValuePath() const
    {
        std::string path = containerPath() + pendingSegment();
        if (!path.empty() && path.front() == '.')
            path.erase(0, 1);
        return path;
    }

    std::string_view m_text;
    std::vector<SceneProblem>& m_problems;
    Document m_document;
    std::vector<Frame> m_frames;
};

// ------------------------------------------------------------------------------------------------
// Validation: reads the document into a World, reporting every problem it meets.

/// |v|, m, without overflow or underflow in the squares (a vector of 1e160 m has a finite length).
Scalar length(const Vec2& v) { return std::hypot(v.x(), v.y()); }

/// What a number must satisfy besides being finite.
enum class Bound {
    Any,
    Positive, ///< > 0
    NonNegative, ///< ≥ 0
    UnitInterval, ///< 0 … 1
};

constexpr std::array<std::string_view, 7> kRootKeys = {"format",  "version", "world", "bodies",
                                                       "springs", "joints",  "lesson"};
constexpr std::array<std::string_view, 4> kWorldKeys = {"gravity", "integrator", "timeStep", "drag"};
constexpr std::array<std::string_view, 13> kBodyKeys = {
    "name",    "shape",       "position", "angle", "velocity", "angularVelocity", "density",
    "mass",    "restitution", "friction", "fixed", "color",    "soft"};
constexpr std::array<std::string_view, 2> kCircleKeys = {"type", "radius"};
constexpr std::array<std::string_view, 3> kEllipseKeys = {"type", "radiusX", "radiusY"};
constexpr std::array<std::string_view, 3> kBoxKeys = {"type", "width", "height"};
constexpr std::array<std::string_view, 2> kPolygonKeys = {"type", "vertices"};
constexpr std::array<std::string_view, 4> kShapeTypes = {"circle", "ellipse", "box", "polygon"};
constexpr std::array<std::string_view, 5> kSoftKeys = {"ellipsesPerSquareMeter", "stiffness", "dampingRatio", "damping",
                                                       "state"};
constexpr std::array<std::string_view, 2> kSoftStateKeys = {"positions", "velocities"};
constexpr std::array<std::string_view, 7> kSpringKeys = {"bodyA",     "anchorA", "bodyB",     "anchorB",
                                                         "stiffness", "damping", "restLength"};
constexpr std::array<std::string_view, 4> kPinKeys = {"type", "bodyA", "bodyB", "anchor"};
constexpr std::array<std::string_view, 5> kRodKeys = {"type", "bodyA", "anchorA", "bodyB", "anchorB"};
constexpr std::array<std::string_view, 2> kJointTypes = {"pin", "rod"};

/// The value `ellipsesPerSquareMeter` takes to ask for SoftSettings::autoDensity.
constexpr std::string_view kAutoDensity = "auto";

const std::array<IntegratorKind, 3> kIntegrators = {IntegratorKind::Euler, IntegratorKind::SemiImplicitEuler,
                                                    IntegratorKind::Rk4};

/// A body reference (`bodyA`, `bodyB`) as read: whether it was valid, and the body if any.
struct BodyRef {
    bool ok = false;
    std::optional<BodyId> id;
};

class SceneReader {
public:
    /// Reads the whole document; the world is only returned when no problem was found.
    std::optional<World> read(const Json& root)
    {
        if (!root.is_object()) {
            report({}, "expected a JSON object (a scene), got " + describe(root));
            return std::nullopt;
        }
        checkKeys(root, {}, kRootKeys);
        // A file that is not a v1 scene would only add noise below: its other keys may mean
        // something else entirely. Say what it is and stop.
        if (!readFormatAndVersion(root))
            return std::nullopt;

        World world;
        if (const Json* settings = find(root, "world"))
            readWorldSettings(*settings, "world", world.settings);
        if (const Json* bodies = require(root, "bodies", {}))
            readBodies(*bodies, "bodies", world.bodies);
        if (const Json* springs = find(root, "springs"))
            readSprings(*springs, "springs", world);
        if (const Json* joints = find(root, "joints"))
            readJoints(*joints, "joints", world);
        if (const Json* lesson = find(root, "lesson"))
            world.lesson = readLesson(*lesson, "lesson", world, m_problems);

        if (!m_problems.empty())
            return std::nullopt;
        return world;
    }

    std::vector<SceneProblem> takeProblems() { return std::move(m_problems); }

private:
    void report(const std::string& path, std::string reason)
    {
        m_problems.push_back(SceneProblem{displayPath(path), std::move(reason)});
    }

    static const Json* find(const Json& object, std::string_view key)
    {
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    const Json* require(const Json& object, std::string_view key, const std::string& path)
    {
        const Json* value = find(object, key);
        if (!value)
            report(path, "missing required key " + singleQuoted(key));
        return value;
    }

    /// Reports every key of `object` that is not in `allowed`; `owner` names the kind of object
    /// when the allowed keys depend on it ("a box").
    void checkKeys(const Json& object, const std::string& path, std::span<const std::string_view> allowed,
                   std::string_view owner = {})
    {
        for (auto it = object.begin(); it != object.end(); ++it) {
            const std::string& key = it.key();
            if (std::find(allowed.begin(), allowed.end(), key) != allowed.end())
                continue;
            std::string reason = "unknown key " + singleQuoted(key);
            if (!owner.empty())
                reason += " for " + std::string(owner);
            const std::optional<std::string> suggestion = nearestName(key, allowed);
            if (suggestion)
                reason += didYouMean(suggestion);
            else if (!owner.empty())
                reason += " (expected: " + joined(allowed) + ")";
            report(path, std::move(reason));
        }
    }

    bool expectObject(const Json& value, const std::string& path)
    {
        if (value.is_object())
            return true;
        report(path, "expected an object, got " + describe(value));
        return false;
    }

    bool expectArray(const Json& value, const std::string& path)
    {
        if (value.is_array())
            return true;
        report(path, "expected an array, got " + describe(value));
        return false;
    }

    std::optional<Scalar> number(const Json& value, const std::string& path, Bound bound)
    {
        if (!value.is_number()) {
            report(path, "expected a number, got " + describe(value));
            return std::nullopt;
        }
        const Scalar x = value.get<Scalar>();
        if (!std::isfinite(x)) {
            report(path, "expected a finite number, got " + describe(value));
            return std::nullopt;
        }
        switch (bound) {
        case Bound::Any:
            break;
        case Bound::Positive:
            if (!(x > 0)) {
                report(path, "must be greater than 0 (got " + describe(value) + ")");
                return std::nullopt;
            }
            break;
        case Bound::NonNegative:
            if (x < 0) {
                report(path, "must be 0 or greater (got " + describe(value) + ")");
                return std::nullopt;
            }
            break;
        case Bound::UnitInterval:
            if (x < 0 || x > 1) {
                report(path, "must be between 0 and 1 (got " + describe(value) + ")");
                return std::nullopt;
            }
            break;
        }
        return x;
    }

    std::optional<Vec2> vector2(const Json& value, const std::string& path)
    {
        if (!value.is_array() || value.size() != 2) {
            report(path, "expected an array of 2 numbers [x, y], got " + describe(value));
            return std::nullopt;
        }
        const std::optional<Scalar> x = number(value[0], elementPath(path, 0), Bound::Any);
        const std::optional<Scalar> y = number(value[1], elementPath(path, 1), Bound::Any);
        if (!x || !y)
            return std::nullopt;
        return Vec2(*x, *y);
    }

    std::optional<std::string> string(const Json& value, const std::string& path)
    {
        if (!value.is_string()) {
            report(path, "expected a string, got " + describe(value));
            return std::nullopt;
        }
        return value.get<std::string>();
    }

    // Optional keys: absent leaves `out` at its default; present but bad is reported.

    void optionalNumber(const Json& object, std::string_view key, const std::string& path, Bound bound,
                        Scalar& out)
    {
        if (const Json* value = find(object, key)) {
            if (const std::optional<Scalar> x = number(*value, memberPath(path, key), bound))
                out = *x;
        }
    }

    void optionalVector2(const Json& object, std::string_view key, const std::string& path, Vec2& out)
    {
        if (const Json* value = find(object, key)) {
            if (const std::optional<Vec2> v = vector2(*value, memberPath(path, key)))
                out = *v;
        }
    }

    void requiredNumber(const Json& object, std::string_view key, const std::string& path, Bound bound,
                        Scalar& out)
    {
        if (const Json* value = require(object, key, path)) {
            if (const std::optional<Scalar> x = number(*value, memberPath(path, key), bound))
                out = *x;
        }
    }

    void requiredVector2(const Json& object, std::string_view key, const std::string& path, Vec2& out)
    {
        if (const Json* value = require(object, key, path)) {
            if (const std::optional<Vec2> v = vector2(*value, memberPath(path, key)))
                out = *v;
        }
    }

    // ---- Document ------------------------------------------------------------------------------

    bool readFormatAndVersion(const Json& root)
    {
        const std::size_t before = m_problems.size();
        if (const Json* format = require(root, "format", {})) {
            if (const std::optional<std::string> name = string(*format, "format"); name && *name != kSceneFormatName)
                report("format", "not an Impetus scene: format is " + describe(*format) + ", expected \"" +
                                     std::string(kSceneFormatName) + "\"");
        }
        if (const Json* version = require(root, "version", {})) {
            const std::string wanted = std::to_string(kSceneFormatVersion);
            if (!version->is_number_integer()) {
                report("version", "expected an integer, got " + describe(*version));
            } else if (version->is_number_unsigned() ? version->get<std::uint64_t>() >
                                                           static_cast<std::uint64_t>(kSceneFormatVersion)
                                                     : version->get<std::int64_t>() > kSceneFormatVersion) {
                report("version", "version " + version->dump() + " is newer than this build reads (version " +
                                      wanted + ")");
            } else if (version->get<std::int64_t>() != kSceneFormatVersion) {
                report("version",
                       "unsupported version " + version->dump() + " (this build reads version " + wanted + ")");
            }
        }
        return m_problems.size() == before;
    }

    void readWorldSettings(const Json& value, const std::string& path, WorldSettings& settings)
    {
        if (!expectObject(value, path))
            return;
        checkKeys(value, path, kWorldKeys);
        optionalVector2(value, "gravity", path, settings.gravity);
        if (const Json* integrator = find(value, "integrator")) {
            const std::string integratorPath = memberPath(path, "integrator");
            if (const std::optional<std::string> name = string(*integrator, integratorPath)) {
                if (const std::optional<IntegratorKind> kind = integratorFromName(*name)) {
                    settings.integrator = *kind;
                } else {
                    std::vector<std::string_view> names;
                    for (const IntegratorKind k : kIntegrators)
                        names.push_back(integratorName(k));
                    report(integratorPath, "unknown integrator " + singleQuoted(*name) + " (expected one of: " +
                                               joined(names) + ")");
                }
            }
        }
        optionalNumber(value, "timeStep", path, Bound::Positive, settings.timeStep);
        optionalNumber(value, "drag", path, Bound::NonNegative, settings.drag);
    }

    // ---- Bodies --------------------------------------------------------------------------------

    void readBodies(const Json& value, const std::string& path, std::vector<Body>& bodies)
    {
        if (!expectArray(value, path))
            return;
        bodies.reserve(value.size());
        for (std::size_t i = 0; i < value.size(); ++i) {
            const std::string bodyPath = elementPath(path, i);
            Body body;
            bool nameOk = false;
            const bool valid = readBody(value[i], bodyPath, body, nameOk);
            if (nameOk) {
                // Keep the first body of a name: references resolve to it, and the message for a
                // later duplicate can say where the name was first used.
                const auto [it, inserted] =
                    m_bodyIds.emplace(body.name, BodyId{static_cast<std::uint32_t>(bodies.size())});
                if (!inserted)
                    report(memberPath(bodyPath, "name"), "duplicate name " + singleQuoted(body.name) + " (" +
                                                             elementPath(path, it->second.index) +
                                                             " already has it)");
            }
            m_bodyValid.push_back(valid);
            bodies.push_back(std::move(body));
        }
    }

    /// Reads one body; true when it has no problem (its derived data is then computed).
    bool readBody(const Json& value, const std::string& path, Body& body, bool& nameOk)
    {
        const std::size_t before = m_problems.size();
        if (!expectObject(value, path))
            return false;
        checkKeys(value, path, kBodyKeys);

        if (const Json* name = require(value, "name", path)) {
            if (std::optional<std::string> text = string(*name, memberPath(path, "name"))) {
                if (text->empty()) {
                    report(memberPath(path, "name"), "must not be empty");
                } else {
                    body.name = std::move(*text);
                    nameOk = true;
                }
            }
        }
        bool shapeOk = false;
        if (const Json* shape = require(value, "shape", path))
            shapeOk = readShape(*shape, memberPath(path, "shape"), body.shape);
        requiredVector2(value, "position", path, body.state.position);
        optionalNumber(value, "angle", path, Bound::Any, body.state.angle);
        optionalVector2(value, "velocity", path, body.state.velocity);
        optionalNumber(value, "angularVelocity", path, Bound::Any, body.state.angularVelocity);

        const Json* density = find(value, "density");
        const Json* mass = find(value, "mass");
        if (density && mass) {
            report(path, "give either 'density' or 'mass', not both");
        } else if (density) {
            if (const std::optional<Scalar> rho = number(*density, memberPath(path, "density"), Bound::Positive))
                body.massSpec = MassSpec{MassMode::Density, *rho};
        } else if (mass) {
            if (const std::optional<Scalar> m = number(*mass, memberPath(path, "mass"), Bound::Positive))
                body.massSpec = MassSpec{MassMode::Mass, *m};
        }

        optionalNumber(value, "restitution", path, Bound::UnitInterval, body.material.restitution);
        optionalNumber(value, "friction", path, Bound::NonNegative, body.material.friction);
        if (const Json* fixed = find(value, "fixed")) {
            if (fixed->is_boolean())
                body.fixed = fixed->get<bool>();
            else
                report(memberPath(path, "fixed"), "expected true or false, got " + describe(*fixed));
        }
        body.color = body.fixed ? kFixedBodyColor : Color{};
        if (const Json* color = find(value, "color")) {
            const std::string colorPath = memberPath(path, "color");
            if (const std::optional<std::string> text = string(*color, colorPath)) {
                if (const std::optional<Color> parsed = Color::fromHex(*text))
                    body.color = *parsed;
                else
                    report(colorPath, "expected a color \"#rrggbb\", got " + describe(*color));
            }
        }
        if (const Json* soft = find(value, "soft"))
            readSoft(*soft, memberPath(path, "soft"), body);

        if (m_problems.size() != before || !shapeOk)
            return false;
        body.updateDerived();
        // Sizes and densities that are each fine can still multiply out to nothing or to
        // infinity (a radius of 1e-200 has an area that underflows to 0); the engine divides by
        // both, so such a body would turn the first step into NaN.
        const bool usable = std::isfinite(body.mass) && body.mass > 0 && std::isfinite(body.inertia) &&
                            body.inertia > 0;
        if (!usable) {
            report(path, "mass or moment of inertia out of range (mass " + describe(Json(body.mass)) +
                             " kg, moment of inertia " + describe(Json(body.inertia)) +
                             " kg·m²): the size or density is too extreme to simulate");
            return false;
        }
        if (body.soft && !checkSoftGridSize(body, memberPath(path, "soft")))
            return false;
        return true;
    }

    /// Refuses a soft body whose grid would have more than kMaxSoftGridCells cells. The grid
    /// builder lays a lattice of density n over the shape's bounding box, about w·h·n cells;
    /// far beyond the cap that count no longer fits its int indices (1e12 per m² once overflowed
    /// them, undefined behaviour) nor the memory.
    bool checkSoftGridSize(const Body& body, const std::string& path)
    {
        Vec2 size = Vec2::Zero();
        if (const auto* circle = std::get_if<Circle>(&body.shape)) {
            size = Vec2::Constant(2 * circle->radius);
        } else if (const auto* ellipse = std::get_if<Ellipse>(&body.shape)) {
            size = Vec2(2 * ellipse->radiusX, 2 * ellipse->radiusY);
        } else {
            Vec2 lower = body.geometry.outline.front();
            Vec2 upper = lower;
            for (const Vec2& v : body.geometry.outline) {
                lower = lower.cwiseMin(v);
                upper = upper.cwiseMax(v);
            }
            size = upper - lower;
        }
        const Scalar density =
            body.soft->autoDensity ? constants::kSoftAutoDensities[0] : body.soft->ellipsesPerSquareMeter;
        const Scalar cells = size.x() * size.y() * density;
        if (cells <= kMaxSoftGridCells)
            return true;
        // Three significant digits: the sizes of such a grid, not their last bits, are the point.
        const auto rounded = [](Scalar x) {
            std::ostringstream text;
            text << std::setprecision(3) << x;
            return text.str();
        };
        const std::string densityText = body.soft->autoDensity
                                            ? "\"auto\" (at least " + rounded(density) + " per m²)"
                                            : rounded(density) + " per m²";
        report(memberPath(path, "ellipsesPerSquareMeter"),
               "a grid of " + rounded(cells) + " ellipses (" + densityText + " over the " + rounded(size.x()) +
                   " m × " + rounded(size.y()) + " m the shape spans), more than the " +
                   rounded(kMaxSoftGridCells) + " a soft body may have");
        return false;
    }

    /// Reads a shape; true when it is complete and valid.
    bool readShape(const Json& value, const std::string& path, Shape& shape)
    {
        const std::size_t before = m_problems.size();
        if (!expectObject(value, path))
            return false;
        const Json* type = require(value, "type", path);
        if (!type)
            return false;
        const std::string typePath = memberPath(path, "type");
        const std::optional<std::string> name = string(*type, typePath);
        if (!name)
            return false;

        if (*name == "circle") {
            checkKeys(value, path, kCircleKeys, "a circle");
            Circle circle;
            requiredNumber(value, "radius", path, Bound::Positive, circle.radius);
            shape = circle;
        } else if (*name == "ellipse") {
            checkKeys(value, path, kEllipseKeys, "an ellipse");
            Ellipse ellipse;
            requiredNumber(value, "radiusX", path, Bound::Positive, ellipse.radiusX);
            requiredNumber(value, "radiusY", path, Bound::Positive, ellipse.radiusY);
            shape = ellipse;
        } else if (*name == "box") {
            checkKeys(value, path, kBoxKeys, "a box");
            Box box;
            requiredNumber(value, "width", path, Bound::Positive, box.width);
            requiredNumber(value, "height", path, Bound::Positive, box.height);
            shape = box;
        } else if (*name == "polygon") {
            checkKeys(value, path, kPolygonKeys, "a polygon");
            Polygon polygon;
            if (const Json* vertices = require(value, "vertices", path))
                readVertices(*vertices, memberPath(path, "vertices"), polygon.vertices);
            shape = std::move(polygon);
        } else {
            report(typePath, "unknown shape type " + singleQuoted(*name) + " (expected one of: " + joined(kShapeTypes) + ")");
        }
        return m_problems.size() == before;
    }

    void readVertices(const Json& value, const std::string& path, std::vector<Vec2>& vertices)
    {
        if (!value.is_array()) {
            report(path, "expected an array of [x, y] points, got " + describe(value));
            return;
        }
        const std::size_t before = m_problems.size();
        vertices.reserve(value.size());
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (const std::optional<Vec2> v = vector2(value[i], elementPath(path, i)))
                vertices.push_back(*v);
        }
        // Only a complete list of finite points is worth judging as a polygon; otherwise the
        // polygon checks would repeat the problems already reported for single vertices.
        if (m_problems.size() != before)
            return;
        for (const PolygonIssue& issue : validatePolygon(vertices))
            report(path, issue.message);
    }

    void readSoft(const Json& value, const std::string& path, Body& body)
    {
        if (!expectObject(value, path))
            return;
        checkKeys(value, path, kSoftKeys);
        SoftSettings settings;
        if (const Json* density = find(value, "ellipsesPerSquareMeter")) {
            const std::string densityPath = memberPath(path, "ellipsesPerSquareMeter");
            if (density->is_string()) {
                if (density->get_ref<const std::string&>() == kAutoDensity)
                    settings.autoDensity = true;
                else
                    report(densityPath, "expected a number or \"auto\", got " + describe(*density));
            } else if (const std::optional<Scalar> n = number(*density, densityPath, Bound::Positive)) {
                settings.ellipsesPerSquareMeter = *n;
            }
        }
        optionalNumber(value, "stiffness", path, Bound::Positive, settings.stiffness);
        // The damping is a ratio ζ (the default) or a coefficient in N·s/m, never both: two
        // sources for one value could disagree.
        const bool hasRatio = find(value, "dampingRatio") != nullptr;
        const bool hasCoefficient = find(value, "damping") != nullptr;
        if (hasRatio && hasCoefficient)
            report(path, "give either 'dampingRatio' or 'damping', not both");
        optionalNumber(value, "dampingRatio", path, Bound::NonNegative, settings.dampingRatio);
        optionalNumber(value, "damping", path, Bound::NonNegative, settings.damping);
        if (hasCoefficient && !hasRatio)
            settings.dampingMode = SoftDampingMode::Coefficient;
        body.soft = settings;
        if (const Json* state = find(value, "state"))
            readSoftState(*state, memberPath(path, "state"), body.softState);
    }

    /// A list of [x, y] vectors, every one finite.
    std::vector<Vec2> vectorList(const Json& value, const std::string& path)
    {
        std::vector<Vec2> list;
        if (!expectArray(value, path))
            return list;
        list.reserve(value.size());
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (const std::optional<Vec2> v = vector2(value[i], elementPath(path, i)))
                list.push_back(*v);
        }
        return list;
    }

    void readSoftState(const Json& value, const std::string& path, std::optional<SoftGridState>& state)
    {
        if (!expectObject(value, path))
            return;
        checkKeys(value, path, kSoftStateKeys);
        const std::size_t before = m_problems.size();
        const Json* positions = require(value, "positions", path);
        const Json* velocities = require(value, "velocities", path);
        if (!positions || !velocities)
            return;
        SoftGridState read;
        read.positions = vectorList(*positions, memberPath(path, "positions"));
        read.velocities = vectorList(*velocities, memberPath(path, "velocities"));
        if (m_problems.size() != before)
            return;
        if (read.positions.empty())
            report(memberPath(path, "positions"), "a grid has at least one ellipse (got an empty list)");
        else if (read.positions.size() != read.velocities.size())
            report(path, "expected one velocity per position (got " + std::to_string(read.positions.size()) +
                             " positions and " + std::to_string(read.velocities.size()) + " velocities)");
        else
            state = std::move(read);
    }

    // ---- Springs and joints ------------------------------------------------------------------

    /// Reads a body reference. A required one (bodyA) must name a body; an optional one (bodyB)
    /// may also be absent or null, meaning the world.
    BodyRef bodyRef(const Json& object, std::string_view key, const std::string& path, bool required)
    {
        const std::string refPath = memberPath(path, key);
        const Json* value = required ? require(object, key, path) : find(object, key);
        if (!value)
            return BodyRef{!required, std::nullopt};
        if (value->is_null() && !required)
            return BodyRef{true, std::nullopt};
        if (!value->is_string()) {
            report(refPath, std::string(required ? "expected a body name" : "expected a body name or null") +
                                ", got " + describe(*value));
            return {};
        }
        const std::string& name = value->get_ref<const std::string&>();
        if (const auto it = m_bodyIds.find(name); it != m_bodyIds.end())
            return BodyRef{true, it->second};
        std::optional<std::string> suggestion;
        if (m_bodySuggestionsLeft > 0) {
            --m_bodySuggestionsLeft;
            if (m_bodyNames.empty()) {
                for (const auto& entry : m_bodyIds)
                    m_bodyNames.push_back(entry.first);
            }
            suggestion = nearestName(name, m_bodyNames);
        }
        report(refPath, "unknown body " + singleQuoted(name) + didYouMean(suggestion));
        return {};
    }

    /// True when both ends are valid and distinct; reports a body attached to itself.
    bool checkEnds(const BodyRef& a, const BodyRef& b, const World& world, const std::string& path,
                   std::string_view what)
    {
        if (!a.ok || !b.ok)
            return false;
        if (b.id && *b.id == *a.id) {
            report(memberPath(path, "bodyB"), std::string(what) + " cannot attach body " +
                                                  singleQuoted(world.body(*a.id).name) + " to itself");
            return false;
        }
        return true;
    }

    /// True when the load-time pose of every body the item refers to is known.
    bool posesKnown(const BodyRef& a, const BodyRef& b) const
    {
        return a.id && m_bodyValid[a.id->index] && (!b.id || m_bodyValid[b.id->index]);
    }

    /// A point given in body B's frame, or in the world when there is no body B.
    static Vec2 worldPointOf(const World& world, const std::optional<BodyId>& body, const Vec2& point)
    {
        return body ? world.body(*body).worldPoint(point) : point;
    }

    void readSprings(const Json& value, const std::string& path, World& world)
    {
        if (!expectArray(value, path))
            return;
        for (std::size_t i = 0; i < value.size(); ++i) {
            const std::string springPath = elementPath(path, i);
            const Json& item = value[i];
            if (!expectObject(item, springPath))
                continue;
            const std::size_t before = m_problems.size();
            checkKeys(item, springPath, kSpringKeys);
            Spring spring;
            const BodyRef a = bodyRef(item, "bodyA", springPath, true);
            const BodyRef b = bodyRef(item, "bodyB", springPath, false);
            const bool endsOk = checkEnds(a, b, world, springPath, "a spring");
            optionalVector2(item, "anchorA", springPath, spring.anchorA);
            optionalVector2(item, "anchorB", springPath, spring.anchorB);
            requiredNumber(item, "stiffness", springPath, Bound::NonNegative, spring.stiffness);
            optionalNumber(item, "damping", springPath, Bound::NonNegative, spring.damping);
            const bool restLengthGiven = find(item, "restLength") != nullptr;
            optionalNumber(item, "restLength", springPath, Bound::NonNegative, spring.restLength);
            if (m_problems.size() != before || !endsOk)
                continue;
            spring.bodyA = *a.id;
            spring.bodyB = b.id;
            if (!restLengthGiven && posesKnown(a, b)) {
                const Vec2 endA = world.body(spring.bodyA).worldPoint(spring.anchorA);
                spring.restLength = length(Vec2(worldPointOf(world, spring.bodyB, spring.anchorB) - endA));
            }
            world.springs.push_back(spring);
        }
    }

    void readJoints(const Json& value, const std::string& path, World& world)
    {
        if (!expectArray(value, path))
            return;
        for (std::size_t i = 0; i < value.size(); ++i) {
            const std::string jointPath = elementPath(path, i);
            const Json& item = value[i];
            if (!expectObject(item, jointPath))
                continue;
            const Json* type = require(item, "type", jointPath);
            if (!type)
                continue;
            const std::string typePath = memberPath(jointPath, "type");
            const std::optional<std::string> name = string(*type, typePath);
            if (!name)
                continue;
            if (*name == "pin") {
                readPin(item, jointPath, world);
            } else if (*name == "rod") {
                readRod(item, jointPath, world);
            } else {
                report(typePath, "unknown joint type " + singleQuoted(*name) + " (expected one of: " +
                                     joined(kJointTypes) + ")");
            }
        }
    }

    void readPin(const Json& item, const std::string& path, World& world)
    {
        const std::size_t before = m_problems.size();
        checkKeys(item, path, kPinKeys, "a pin joint");
        Joint joint;
        joint.type = JointType::Pin;
        const BodyRef a = bodyRef(item, "bodyA", path, true);
        const BodyRef b = bodyRef(item, "bodyB", path, false);
        const bool endsOk = checkEnds(a, b, world, path, "a joint");
        requiredVector2(item, "anchor", path, joint.worldAnchor);
        if (m_problems.size() != before || !endsOk)
            return;
        joint.bodyA = *a.id;
        joint.bodyB = b.id;
        if (posesKnown(a, b))
            derivePinAnchors(world, joint); // the hinge is given once, in the world
        world.joints.push_back(joint);
    }

    void readRod(const Json& item, const std::string& path, World& world)
    {
        const std::size_t before = m_problems.size();
        checkKeys(item, path, kRodKeys, "a rod joint");
        Joint joint;
        joint.type = JointType::Rod;
        const BodyRef a = bodyRef(item, "bodyA", path, true);
        const BodyRef b = bodyRef(item, "bodyB", path, false);
        const bool endsOk = checkEnds(a, b, world, path, "a joint");
        optionalVector2(item, "anchorA", path, joint.anchorA);
        optionalVector2(item, "anchorB", path, joint.anchorB);
        if (m_problems.size() != before || !endsOk)
            return;
        joint.bodyA = *a.id;
        joint.bodyB = b.id;
        if (posesKnown(a, b)) {
            const Vec2 endA = world.body(joint.bodyA).worldPoint(joint.anchorA);
            const Vec2 endB = worldPointOf(world, joint.bodyB, joint.anchorB);
            // hypot, not norm(): the squares of a length of 1e160 m overflow, and an infinite
            // length once made a rod that long "zero length" (infinity is not above infinity).
            joint.length = length(Vec2(endB - endA));
            // A rod keeps a direction as well as a length; with both ends on one point it has
            // none. "One point" is judged relative to how far from the origin the ends are, since
            // the rotation that places the anchors rounds at that scale.
            const Scalar scale = std::max({Scalar(1), length(endA), length(endB)});
            if (!(joint.length > constants::kRelativePointTolerance * scale)) {
                report(path, "rod has zero length: its two anchors are at the same point at load time");
                return;
            }
        }
        world.joints.push_back(joint);
    }

    std::vector<SceneProblem> m_problems;
    /// Body name → id of the first body with that name.
    std::map<std::string, BodyId, std::less<>> m_bodyIds;
    /// Per body: read without problems, so its pose can place anchors.
    std::vector<bool> m_bodyValid;
    /// The keys of m_bodyIds, listed once for suggestions (springs and joints come after bodies).
    std::vector<std::string_view> m_bodyNames;
    int m_bodySuggestionsLeft = kMaxBodySuggestions;
};

// ------------------------------------------------------------------------------------------------
// Writing

OrderedJson vectorJson(const Vec2& v) { return OrderedJson::array({v.x(), v.y()}); }

OrderedJson shapeJson(const Shape& shape)
{
    OrderedJson out = OrderedJson::object();
    out["type"] = std::string(shapeTypeName(shape));
    if (const auto* circle = std::get_if<Circle>(&shape)) {
        out["radius"] = circle->radius;
    } else if (const auto* ellipse = std::get_if<Ellipse>(&shape)) {
        out["radiusX"] = ellipse->radiusX;
        out["radiusY"] = ellipse->radiusY;
    } else if (const auto* box = std::get_if<Box>(&shape)) {
        out["width"] = box->width;
        out["height"] = box->height;
    } else if (const auto* polygon = std::get_if<Polygon>(&shape)) {
        OrderedJson vertices = OrderedJson::array();
        for (const Vec2& v : polygon->vertices)
            vertices.push_back(vectorJson(v));
        out["vertices"] = std::move(vertices);
    }
    return out;
}

/// A soft grid's state: written when the grid has moved on its own (a step deformed it), so that a
/// scene saved mid-run continues exactly. A grid that is still a rigid copy of its body, or a body
/// without a grid, is written without it and gets a fresh grid at load, as before.
std::optional<OrderedJson> softStateJson(const Body& body, const SoftGrid* grid)
{
    const SoftGridState* state = nullptr;
    SoftGridState fromGrid;
    // A grid that no longer describes its body (edited since the run: it is placed or built again
    // at the next step) is not saved either.
    const bool current = grid && body.soft && grid->shape == body.shape && grid->massSpec == body.massSpec &&
                         grid->settings == *body.soft && grid->ownerState == body.state;
    if (current && !grid->rigidCopy) {
        fromGrid.positions = grid->positions;
        fromGrid.velocities = grid->velocities;
        state = &fromGrid;
    } else if (body.softState) {
        // Read from a file and not yet built into a grid: kept as it was.
        state = &*body.softState;
    }
    if (!state)
        return std::nullopt;
    OrderedJson positions = OrderedJson::array();
    for (const Vec2& p : state->positions)
        positions.push_back(vectorJson(p));
    OrderedJson velocities = OrderedJson::array();
    for (const Vec2& v : state->velocities)
        velocities.push_back(vectorJson(v));
    OrderedJson out = OrderedJson::object();
    out["positions"] = std::move(positions);
    out["velocities"] = std::move(velocities);
    return out;
}

OrderedJson bodyJson(const Body& body, const SoftGrid* grid)
{
    OrderedJson out = OrderedJson::object();
    out["name"] = body.name;
    out["shape"] = shapeJson(body.shape);
    out["position"] = vectorJson(body.state.position);
    out["angle"] = body.state.angle;
    out["velocity"] = vectorJson(body.state.velocity);
    out["angularVelocity"] = body.state.angularVelocity;
    out[body.massSpec.mode == MassMode::Mass ? "mass" : "density"] = body.massSpec.value;
    out["restitution"] = body.material.restitution;
    out["friction"] = body.material.friction;
    out["fixed"] = body.fixed;
    out["color"] = body.color.toHex();
    if (body.soft) {
        OrderedJson soft = OrderedJson::object();
        if (body.soft->autoDensity)
            soft["ellipsesPerSquareMeter"] = std::string(kAutoDensity);
        else
            soft["ellipsesPerSquareMeter"] = body.soft->ellipsesPerSquareMeter;
        soft["stiffness"] = body.soft->stiffness;
        if (body.soft->dampingMode == SoftDampingMode::Ratio)
            soft["dampingRatio"] = body.soft->dampingRatio;
        else
            soft["damping"] = body.soft->damping;
        if (std::optional<OrderedJson> state = softStateJson(body, grid))
            soft["state"] = std::move(*state);
        out["soft"] = std::move(soft);
    }
    return out;
}

/// A body reference by name. An id outside the world (which a valid world never has) is written
/// as null rather than crashing the save.
OrderedJson bodyRefJson(const World& world, const std::optional<BodyId>& id)
{
    if (!id || id->index >= world.bodies.size())
        return nullptr;
    return world.body(*id).name;
}

OrderedJson springJson(const World& world, const Spring& spring)
{
    OrderedJson out = OrderedJson::object();
    out["bodyA"] = bodyRefJson(world, spring.bodyA);
    out["anchorA"] = vectorJson(spring.anchorA);
    out["bodyB"] = bodyRefJson(world, spring.bodyB);
    out["anchorB"] = vectorJson(spring.anchorB);
    out["stiffness"] = spring.stiffness;
    out["damping"] = spring.damping;
    out["restLength"] = spring.restLength;
    return out;
}

OrderedJson jointJson(const World& world, const Joint& joint)
{
    OrderedJson out = OrderedJson::object();
    if (joint.type == JointType::Pin) {
        // The derived body-frame anchors are not written: they follow from the world anchor and
        // the poses, and writing them would give two sources of truth that could disagree.
        out["type"] = "pin";
        out["bodyA"] = bodyRefJson(world, joint.bodyA);
        out["bodyB"] = bodyRefJson(world, joint.bodyB);
        out["anchor"] = vectorJson(joint.worldAnchor);
    } else {
        out["type"] = "rod";
        out["bodyA"] = bodyRefJson(world, joint.bodyA);
        out["anchorA"] = vectorJson(joint.anchorA);
        out["bodyB"] = bodyRefJson(world, joint.bodyB);
        out["anchorB"] = vectorJson(joint.anchorB);
    }
    return out;
}

OrderedJson sceneJson(const World& world)
{
    OrderedJson out = OrderedJson::object();
    out["format"] = std::string(kSceneFormatName);
    out["version"] = kSceneFormatVersion;
    OrderedJson settings = OrderedJson::object();
    settings["gravity"] = vectorJson(world.settings.gravity);
    settings["integrator"] = std::string(integratorName(world.settings.integrator));
    settings["timeStep"] = world.settings.timeStep;
    settings["drag"] = world.settings.drag;
    out["world"] = std::move(settings);
    OrderedJson bodies = OrderedJson::array();
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i)
        bodies.push_back(bodyJson(world.bodies[i], world.softGrid(BodyId{i})));
    out["bodies"] = std::move(bodies);
    OrderedJson springs = OrderedJson::array();
    for (const Spring& spring : world.springs)
        springs.push_back(springJson(world, spring));
    out["springs"] = std::move(springs);
    OrderedJson joints = OrderedJson::array();
    for (const Joint& joint : world.joints)
        joints.push_back(jointJson(world, joint));
    out["joints"] = std::move(joints);
    if (world.lesson)
        out["lesson"] = lessonJson(*world.lesson, world);
    return out;
}

bool isScalar(const OrderedJson& value) { return !value.is_object() && !value.is_array(); }

/// Pretty-prints like dump(2), except that an array of plain values ([x, y]) stays on one line,
/// as people write them; a polygon then reads one vertex per line.
void writePretty(const OrderedJson& value, std::size_t depth, std::string& out)
{
    if (isScalar(value)) {
        // nlohmann writes a double in the shortest form that reads back to the same bits, which
        // is what makes parseScene(serializeScene(w)) == w exact. Invalid UTF-8 in a name (only
        // an editor bug could put it there) is replaced rather than thrown.
        out += value.dump(-1, ' ', false, OrderedJson::error_handler_t::replace);
        return;
    }
    const bool isObject = value.is_object();
    const char open = isObject ? '{' : '[';
    const char close = isObject ? '}' : ']';
    if (value.empty()) {
        out += open;
        out += close;
        return;
    }
    if (!isObject && std::all_of(value.begin(), value.end(), isScalar)) {
        out += open;
        for (auto it = value.begin(); it != value.end(); ++it) {
            if (it != value.begin())
                out += ", ";
            writePretty(*it, depth + 1, out);
        }
        out += close;
        return;
    }
    const std::string innerIndent((depth + 1) * kIndentWidth, ' ');
    out += open;
    out += '\n';
    for (auto it = value.begin(); it != value.end(); ++it) {
        if (it != value.begin())
            out += ",\n";
        out += innerIndent;
        if (isObject) {
            out += OrderedJson(it.key()).dump(-1, ' ', false, OrderedJson::error_handler_t::replace);
            out += ": ";
        }
        writePretty(it.value(), depth + 1, out);
    }
    out += '\n';
    out += std::string(depth * kIndentWidth, ' ');
    out += close;
}

// ------------------------------------------------------------------------------------------------
// Files

std::string errorText(int error) { return std::error_code(error, std::generic_category()).message(); }

std::string quotedPath(const fs::path& path) { return '\'' + path.string() + '\''; }

SceneLoadResult fileProblem(std::string reason)
{
    return SceneLoadResult{std::nullopt, {SceneProblem{std::string(kFilePath), std::move(reason)}}};
}

/// Why a path that exists is not read: what kind of file it is.
std::string notRegularReason(const fs::file_status& status)
{
    switch (status.type()) {
    case fs::file_type::character:
    case fs::file_type::block:
        return "it is a device, not a regular file";
    case fs::file_type::fifo:
        return "it is a pipe (FIFO), not a regular file";
    case fs::file_type::socket:
        return "it is a socket, not a regular file";
    default:
        return "it is not a regular file";
    }
}

/// The reason a file over kMaxSceneFileBytes is not read.
std::string tooLargeReason(const fs::path& path)
{
    constexpr std::uintmax_t kMebibyte = 1024 * 1024;
    return "cannot read " + quotedPath(path) + ": the file is larger than the " +
           std::to_string(kMaxSceneFileBytes / kMebibyte) + " MiB (" + std::to_string(kMaxSceneFileBytes) +
           " bytes) a scene file may have";
}

std::string saveFailure(const fs::path& path, const std::string& reason)
{
    return "cannot save " + quotedPath(path) + ": " + reason;
}

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using FileHandle = std::unique_ptr<std::FILE, FileCloser>;

/// Flushes `file` to the disk. Without it a crash right after the rename could leave the new
/// name pointing at data that never reached the disk, on some file systems an empty file.
bool syncToDisk([[maybe_unused]] std::FILE* file)
{
#ifdef IMPETUS_SCENE_IO_POSIX
    return ::fsync(::fileno(file)) == 0;
#else
    return true;
#endif
}

/// Makes the rename itself durable. Best effort: some file systems cannot sync a directory, and
/// the file is already complete under its new name either way.
void syncDirectory([[maybe_unused]] const fs::path& directory)
{
#ifdef IMPETUS_SCENE_IO_POSIX
    const int fd = ::open(directory.c_str(), O_RDONLY);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
#endif
}

/// Creates a new, empty temporary file next to `target` and opens it for writing. Fails rather
/// than reuse a name that exists ("x" mode), so it never clobbers anyone else's file.
std::pair<FileHandle, fs::path> createTemporary(const fs::path& target, int& error)
{
    std::random_device seed;
    std::mt19937_64 random(seed());
    const fs::path directory = target.parent_path();
    error = 0;
    for (int attempt = 0; attempt < kTempNameAttempts; ++attempt) {
        const fs::path candidate =
            directory / ("." + target.filename().string() + ".tmp-" + std::to_string(random()));
        errno = 0;
        FileHandle file(std::fopen(candidate.string().c_str(), "wbx"));
        if (file)
            return {std::move(file), candidate};
        error = errno;
        if (error != EEXIST)
            break;
    }
    return {FileHandle(), fs::path()};
}

/// Writes `text` to `target` through a temporary file and a rename, so `target` is at every
/// moment either the old file or the complete new one. Returns the reason on failure.
std::optional<std::string> writeAtomically(const fs::path& target, const std::string& text)
{
    std::error_code ec;
    const fs::file_status status = fs::status(target, ec);
    if (fs::is_directory(status))
        return std::string("it is a directory");

    int error = 0;
    std::pair<FileHandle, fs::path> created = createTemporary(target, error);
    FileHandle& file = created.first;
    const fs::path& temporary = created.second;
    if (!file) {
        const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
        return "cannot create a temporary file in " + quotedPath(directory) + ": " + errorText(error);
    }

    const auto fail = [&temporary](int code, const std::string& what) -> std::optional<std::string> {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        return what + ": " + errorText(code);
    };

    errno = 0;
    if (std::fwrite(text.data(), 1, text.size(), file.get()) != text.size())
        return fail(errno, "cannot write");
    if (std::fflush(file.get()) != 0 || !syncToDisk(file.get()))
        return fail(errno, "cannot write");
    std::FILE* raw = file.release();
    if (std::fclose(raw) != 0)
        return fail(errno, "cannot write");

    // Keep the permissions the user gave the file (a read-only group bit, say); a new file would
    // otherwise get the process's default ones.
    if (fs::exists(status))
        fs::permissions(temporary, status.permissions(), ec);

    fs::rename(temporary, target, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        return "cannot replace the file: " + ec.message();
    }
    syncDirectory(target.parent_path().empty() ? fs::path(".") : target.parent_path());
    return std::nullopt;
}

} // namespace

SceneLoadResult parseScene(std::string_view jsonText)
{
    try {
        std::vector<SceneProblem> problems;
        DocumentBuilder builder(jsonText, problems);
        const bool parsed = Json::sax_parse(jsonText.data(), jsonText.data() + jsonText.size(), &builder);
        if (!parsed)
            return SceneLoadResult{std::nullopt, std::move(problems)};
        const Document document(builder.takeDocument());

        SceneReader reader;
        std::optional<World> world = reader.read(document.get());
        std::vector<SceneProblem> found = reader.takeProblems();
        // Repeated keys (found while parsing) come first: they are about the text itself.
        problems.insert(problems.end(), std::make_move_iterator(found.begin()), std::make_move_iterator(found.end()));
        if (!problems.empty())
            return SceneLoadResult{std::nullopt, std::move(problems)};
        return SceneLoadResult{std::move(world), {}};
    } catch (const std::bad_alloc&) {
        // The document was freed on the way here (Document), so this message has memory again.
        return SceneLoadResult{std::nullopt, {SceneProblem{std::string(kRootPath), outOfMemoryReason(jsonText.size())}}};
    } catch (const std::exception& error) {
        // Nothing else is known to throw; the promise is a message, never a crash.
        return SceneLoadResult{std::nullopt,
                               {SceneProblem{std::string(kRootPath),
                                             std::string("cannot read the scene: ") + error.what()}}};
    }
}

SceneLoadResult loadSceneFile(const std::filesystem::path& path)
{
    try {
        // Judge the file before opening it: opening a pipe blocks until someone writes to it,
        // and a device such as /dev/zero never ends.
        std::error_code ec;
        const fs::file_status status = fs::status(path, ec);
        if (fs::is_directory(status))
            return fileProblem("cannot open " + quotedPath(path) + ": it is a directory");
        if (fs::exists(status) && !fs::is_regular_file(status))
            return fileProblem("cannot open " + quotedPath(path) + ": " + notRegularReason(status));
        if (fs::is_regular_file(status)) {
            const std::uintmax_t size = fs::file_size(path, ec);
            if (!ec && size > kMaxSceneFileBytes)
                return fileProblem(tooLargeReason(path));
        }
        errno = 0;
        const FileHandle file(std::fopen(path.string().c_str(), "rb"));
        if (!file)
            return fileProblem("cannot open " + quotedPath(path) + ": " + errorText(errno));
        // The read stops one byte past the cap whatever the file claimed to be, so a file that
        // grows while it is read (or one replaced by a device in between) cannot run away.
        std::string text;
        std::vector<char> chunk(kReadChunkBytes);
        std::size_t got = 0;
        while ((got = std::fread(chunk.data(), 1, chunk.size(), file.get())) > 0) {
            text.append(chunk.data(), got);
            if (text.size() > kMaxSceneFileBytes)
                return fileProblem(tooLargeReason(path));
        }
        if (std::ferror(file.get()))
            return fileProblem("cannot read " + quotedPath(path) + ": " + errorText(errno));
        return parseScene(text);
    } catch (const std::bad_alloc&) {
        return fileProblem("cannot read " + quotedPath(path) + ": out of memory");
    } catch (const std::exception& error) {
        return fileProblem("cannot read " + quotedPath(path) + ": " + error.what());
    }
}

std::string serializeScene(const World& world)
{
    std::string out;
    writePretty(sceneJson(world), 0, out);
    out += '\n';
    return out;
}

std::optional<std::string> saveSceneFile(const std::filesystem::path& path, const World& world)
{
    try {
        const std::string text = serializeScene(world);
        // Never replace a file with one that cannot be opened again: that would lose the user's
        // last good scene as surely as a half-written file.
        const SceneLoadResult check = parseScene(text);
        if (!check.ok()) {
            std::string reason = "the scene is not valid: ";
            const std::size_t shown = std::min(check.problems.size(), kMaxProblemsInSaveMessage);
            for (std::size_t i = 0; i < shown; ++i)
                reason += (i > 0 ? "; " : "") + check.problems[i].toString();
            if (check.problems.size() > shown)
                reason += "; and " + std::to_string(check.problems.size() - shown) + " more";
            return saveFailure(path, reason);
        }

        fs::path target = path;
        std::error_code ec;
        // Saving through a symbolic link updates the file it points to and keeps the link.
        if (fs::is_symlink(fs::symlink_status(path, ec))) {
            const fs::path resolved = fs::canonical(path, ec);
            if (!ec)
                target = resolved;
        }
        if (const std::optional<std::string> failure = writeAtomically(target, text))
            return saveFailure(path, *failure);
        return std::nullopt;
    } catch (const std::exception& error) {
        return saveFailure(path, error.what());
    }
}

} // namespace impetus::model
