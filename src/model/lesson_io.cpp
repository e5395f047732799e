#include "model/lesson_io.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string_view>

namespace impetus::model {

namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

constexpr std::array<std::string_view, 7> kLessonKeys = {"title",           "instructions",   "editable",
                                                         "editableWorld",   "editableSprings", "editableJoints",
                                                         "questions"};
constexpr std::array<std::string_view, 2> kEditableKeys = {"body", "attributes"};
constexpr std::array<std::string_view, 2> kEditableSpringKeys = {"spring", "attributes"};
constexpr std::array<std::string_view, 2> kEditableJointKeys = {"joint", "attributes"};
constexpr std::array<std::string_view, 4> kQuestionKeys = {"prompt", "answer", "unit", "tolerance"};

/// Strings from the file quoted in a message are cut to this many bytes, so a stray long value
/// cannot bury the message.
constexpr std::size_t kQuotedLength = 40;

/// A UTF-8 continuation byte is 10xxxxxx: (byte & mask) == bits. A cut must not split a character.
constexpr unsigned char kContinuationMask = 0xc0;
constexpr unsigned char kContinuationBits = 0x80;

/// `text` cut to kQuotedLength bytes (with "…" when cut), escaped as in JSON, between `quote`s:
/// printable whatever bytes the file held.
std::string quoted(const std::string& text, char quote)
{
    std::size_t end = std::min(text.size(), kQuotedLength);
    while (end < text.size() && end > 0 && (static_cast<unsigned char>(text[end]) & kContinuationMask) == kContinuationBits)
        --end;
    const std::string literal = Json(text.substr(0, end)).dump(-1, ' ', false, Json::error_handler_t::replace);
    return quote + literal.substr(1, literal.size() - 2) + (end < text.size() ? "…" : "") + quote;
}

/// Collects the problems of one lesson block, each under its JSON path.
class LessonReader {
public:
    LessonReader(const World& world, std::vector<SceneProblem>& problems)
        : m_world(world)
        , m_problems(problems)
    {
    }

    std::optional<Lesson> read(const Json& value, const std::string& path)
    {
        const std::size_t before = m_problems.size();
        if (!isObject(value, path))
            return std::nullopt;
        checkKeys(value, path, kLessonKeys);
        Lesson lesson;
        if (const Json* title = required(value, "title", path)) {
            if (std::optional<std::string> text = string(*title, path + ".title", true))
                lesson.title = std::move(*text);
        }
        if (const Json* instructions = find(value, "instructions")) {
            if (std::optional<std::string> text = string(*instructions, path + ".instructions", false))
                lesson.instructions = std::move(*text);
        }
        if (const Json* editable = find(value, "editable"))
            readEditable(*editable, path + ".editable", lesson);
        if (const Json* world = find(value, "editableWorld"))
            readEditableWorld(*world, path + ".editableWorld", lesson.editableWorld);
        if (const Json* springs = find(value, "editableSprings")) {
            readEditableItems<SpringAttribute, kSpringAttributeCount>(
                *springs, path + ".editableSprings", {"spring", m_world.springs.size(), kEditableSpringKeys},
                springAttributeFromName, kSpringAttributes,
                [&lesson](std::size_t spring, SpringAttributes attributes) { lesson.setEditableSpring(spring, attributes); });
        }
        if (const Json* joints = find(value, "editableJoints")) {
            readEditableItems<JointAttribute, kJointAttributeCount>(
                *joints, path + ".editableJoints", {"joint", m_world.joints.size(), kEditableJointKeys},
                jointAttributeFromName, kJointAttributes,
                [&lesson](std::size_t joint, JointAttributes attributes) { lesson.setEditableJoint(joint, attributes); });
        }
        if (const Json* questions = find(value, "questions"))
            readQuestions(*questions, path + ".questions", lesson.questions);
        if (m_problems.size() != before)
            return std::nullopt;
        return lesson;
    }

private:
    void report(const std::string& path, std::string reason) { m_problems.push_back({path, std::move(reason)}); }

    static const Json* find(const Json& object, std::string_view key)
    {
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    const Json* required(const Json& object, std::string_view key, const std::string& path)
    {
        const Json* value = find(object, key);
        if (!value)
            report(path, "missing required key '" + std::string(key) + "'");
        return value;
    }

    /// How a value is named in a message ("got 3", "got an array", a string in double quotes).
    static std::string kindOf(const Json& value)
    {
        if (value.is_string())
            return quoted(value.get_ref<const std::string&>(), '"');
        if (value.is_object())
            return "an object";
        if (value.is_array())
            return "an array";
        return value.dump();
    }

    void checkKeys(const Json& object, const std::string& path, std::span<const std::string_view> allowed)
    {
        for (auto it = object.begin(); it != object.end(); ++it) {
            if (std::find(allowed.begin(), allowed.end(), it.key()) != allowed.end())
                continue;
            std::string expected;
            for (const std::string_view key : allowed)
                expected += (expected.empty() ? "" : ", ") + std::string(key);
            report(path, "unknown key " + quoted(it.key(), '\'') + " (expected: " + expected + ")");
        }
    }

    bool isObject(const Json& value, const std::string& path)
    {
        if (value.is_object())
            return true;
        report(path, "expected an object, got " + kindOf(value));
        return false;
    }

    bool isArray(const Json& value, const std::string& path)
    {
        if (value.is_array())
            return true;
        report(path, "expected an array, got " + kindOf(value));
        return false;
    }

    std::optional<std::string> string(const Json& value, const std::string& path, bool nonEmpty)
    {
        if (!value.is_string()) {
            report(path, "expected a string, got " + kindOf(value));
            return std::nullopt;
        }
        if (nonEmpty && value.get_ref<const std::string&>().empty()) {
            report(path, "must not be empty");
            return std::nullopt;
        }
        return value.get<std::string>();
    }

    std::optional<Scalar> number(const Json& value, const std::string& path)
    {
        if (!value.is_number()) {
            report(path, "expected a number, got " + kindOf(value));
            return std::nullopt;
        }
        const Scalar x = value.get<Scalar>();
        if (!std::isfinite(x)) {
            report(path, "expected a finite number");
            return std::nullopt;
        }
        return x;
    }

    void readEditable(const Json& value, const std::string& path, Lesson& lesson)
    {
        if (!isArray(value, path))
            return;
        std::vector<std::string> seenAt(m_world.bodies.size());
        for (std::size_t i = 0; i < value.size(); ++i) {
            const std::string entryPath = path + '[' + std::to_string(i) + ']';
            const Json& entry = value[i];
            if (!isObject(entry, entryPath))
                continue;
            checkKeys(entry, entryPath, kEditableKeys);
            // A plain id and a flag rather than an optional, which GCC's flow analysis at -O3
            // wrongly takes for uninitialised.
            BodyId body;
            bool known = false;
            if (const Json* name = required(entry, "body", entryPath)) {
                if (const std::optional<std::string> text = string(*name, entryPath + ".body", true)) {
                    const std::optional<BodyId> found = m_world.findBody(*text);
                    if (!found) {
                        report(entryPath + ".body", "unknown body " + quoted(*text, '\''));
                    } else if (!seenAt[found->index].empty()) {
                        report(entryPath + ".body", "body " + quoted(*text, '\'') + " is listed twice (" +
                                                        seenAt[found->index] + " already lists it)");
                    } else {
                        seenAt[found->index] = entryPath;
                        body = *found;
                        known = true;
                    }
                }
            }
            BodyAttributes attributes;
            if (const Json* list = required(entry, "attributes", entryPath)) {
                attributes = readNames<BodyAttribute, kBodyAttributeCount>(*list, entryPath + ".attributes",
                                                                           bodyAttributeFromName, kBodyAttributes);
                // An entry that unlocks nothing is a mistake rather than a lock: leaving the body
                // out locks it.
                if (list->is_array() && list->empty())
                    report(entryPath + ".attributes", "must list at least one attribute (leave the body out to lock it)");
            }
            if (known && attributes.any())
                lesson.setEditable(body, attributes);
        }
    }

    /// What an entry of editableSprings or editableJoints refers to: the key that holds its
    /// index ("spring", "joint", also the noun of the messages), how many the scene has, and the
    /// keys an entry may have.
    struct IndexedItems {
        std::string_view noun;
        std::size_t count = 0;
        std::span<const std::string_view> keys;
    };

    /// Reads a list of {noun: index, attributes: [...]} entries (editableSprings, editableJoints)
    /// and hands each valid one to `set`.
    template <class Attribute, std::size_t N, class FromName, class Set>
    void readEditableItems(const Json& value, const std::string& path, const IndexedItems& items, FromName fromName,
                           const std::array<Attribute, N>& all, Set set)
    {
        if (!isArray(value, path))
            return;
        const std::string noun(items.noun);
        const std::size_t count = items.count;
        std::vector<std::string> seenAt(count);
        for (std::size_t i = 0; i < value.size(); ++i) {
            const std::string entryPath = path + '[' + std::to_string(i) + ']';
            const Json& entry = value[i];
            if (!isObject(entry, entryPath))
                continue;
            checkKeys(entry, entryPath, items.keys);
            std::size_t item = 0;
            bool known = false;
            if (const Json* index = required(entry, items.noun, entryPath)) {
                const std::string indexPath = entryPath + '.' + noun;
                if (!index->is_number_integer()) {
                    report(indexPath, "expected the index of a " + noun + " (a whole number), got " + kindOf(*index));
                } else if (index->is_number_unsigned() ? index->get<std::uint64_t>() >= count
                                                       : index->get<std::int64_t>() < 0 ||
                                                             static_cast<std::uint64_t>(index->get<std::int64_t>()) >= count) {
                    report(indexPath, "no " + noun + ' ' + index->dump() +
                                          (count == 0   ? " (the scene has no " + noun + "s)"
                                           : count == 1 ? " (the scene has 1 " + noun + ", index 0)"
                                                        : " (the scene has " + std::to_string(count) + ' ' + noun +
                                                              "s, indices 0 to " + std::to_string(count - 1) + ")"));
                } else {
                    item = static_cast<std::size_t>(index->get<std::uint64_t>());
                    if (!seenAt[item].empty()) {
                        report(indexPath, noun + ' ' + std::to_string(item) + " is listed twice (" + seenAt[item] +
                                              " already lists it)");
                    } else {
                        seenAt[item] = entryPath;
                        known = true;
                    }
                }
            }
            std::bitset<N> attributes;
            if (const Json* list = required(entry, "attributes", entryPath)) {
                attributes = readNames<Attribute, N>(*list, entryPath + ".attributes", fromName, all);
                if (list->is_array() && list->empty())
                    report(entryPath + ".attributes",
                           "must list at least one attribute (leave the " + noun + " out to lock it)");
            }
            if (known && attributes.any())
                set(item, attributes);
        }
    }

    void readEditableWorld(const Json& value, const std::string& path, WorldAttributes& attributes)
    {
        attributes = readNames<WorldAttribute, kWorldAttributeCount>(value, path, worldAttributeFromName,
                                                                     kWorldAttributes);
    }

    /// Reads an array of attribute names into a set; reports unknown and repeated names.
    template <class Attribute, std::size_t N, class Parse>
    std::bitset<N> readNames(const Json& value, const std::string& path, Parse parse,
                             const std::array<Attribute, N>& all)
    {
        std::bitset<N> set;
        if (!isArray(value, path))
            return set;
        for (std::size_t i = 0; i < value.size(); ++i) {
            const std::string itemPath = path + '[' + std::to_string(i) + ']';
            const std::optional<std::string> name = string(value[i], itemPath, false);
            if (!name)
                continue;
            const std::optional<Attribute> attribute = parse(*name);
            if (!attribute) {
                std::string expected;
                for (const Attribute a : all)
                    expected += (expected.empty() ? "" : ", ") + std::string(attributeName(a));
                report(itemPath, "unknown attribute " + quoted(*name, '\'') + " (expected one of: " + expected + ")");
                continue;
            }
            const auto bit = static_cast<std::size_t>(*attribute);
            if (set.test(bit))
                report(itemPath, "attribute " + quoted(*name, '\'') + " is listed twice");
            set.set(bit);
        }
        return set;
    }

    void readQuestions(const Json& value, const std::string& path, std::vector<LessonQuestion>& questions)
    {
        if (!isArray(value, path))
            return;
        for (std::size_t i = 0; i < value.size(); ++i) {
            const std::string itemPath = path + '[' + std::to_string(i) + ']';
            const Json& item = value[i];
            if (!isObject(item, itemPath))
                continue;
            checkKeys(item, itemPath, kQuestionKeys);
            LessonQuestion question;
            if (const Json* prompt = required(item, "prompt", itemPath)) {
                if (std::optional<std::string> text = string(*prompt, itemPath + ".prompt", true))
                    question.prompt = std::move(*text);
            }
            if (const Json* answer = required(item, "answer", itemPath)) {
                if (const std::optional<Scalar> x = number(*answer, itemPath + ".answer"))
                    question.answer = *x;
            }
            if (const Json* unit = find(item, "unit")) {
                if (std::optional<std::string> text = string(*unit, itemPath + ".unit", false))
                    question.unit = std::move(*text);
            }
            if (const Json* tolerance = required(item, "tolerance", itemPath)) {
                const std::string tolerancePath = itemPath + ".tolerance";
                if (const std::optional<Scalar> x = number(*tolerance, tolerancePath)) {
                    // A tolerance of 0 would accept only the exact binary number, which no one can type.
                    if (*x > 0)
                        question.tolerance = *x;
                    else
                        report(tolerancePath, "must be greater than 0 (got " + kindOf(*tolerance) + ")");
                }
            }
            questions.push_back(std::move(question));
        }
    }

    const World& m_world;
    std::vector<SceneProblem>& m_problems;
};

template <class Attribute, std::size_t N>
OrderedJson namesJson(const std::bitset<N>& set, const std::array<Attribute, N>& all)
{
    OrderedJson names = OrderedJson::array();
    for (const Attribute attribute : all) {
        if (set.test(static_cast<std::size_t>(attribute)))
            names.push_back(std::string(attributeName(attribute)));
    }
    return names;
}

/// editableSprings or editableJoints as written: each entry as {key: index, attributes: [...]},
/// those whose index is past the `count` items of the world left out.
template <class Entry, class Attribute, std::size_t N>
OrderedJson indexedJson(const std::vector<Entry>& entries, std::size_t count, const char* key,
                        const std::array<Attribute, N>& all, std::size_t Entry::*index)
{
    OrderedJson out = OrderedJson::array();
    for (const Entry& entry : entries) {
        if (entry.*index >= count || entry.attributes.none())
            continue;
        OrderedJson item = OrderedJson::object();
        item[key] = entry.*index;
        item["attributes"] = namesJson(entry.attributes, all);
        out.push_back(std::move(item));
    }
    return out;
}

} // namespace

std::optional<Lesson> readLesson(const nlohmann::json& value, const std::string& path, const World& world,
                                 std::vector<SceneProblem>& problems)
{
    return LessonReader(world, problems).read(value, path);
}

nlohmann::ordered_json lessonJson(const Lesson& lesson, const World& world)
{
    OrderedJson out = OrderedJson::object();
    out["title"] = lesson.title;
    out["instructions"] = lesson.instructions;
    OrderedJson editable = OrderedJson::array();
    for (const EditableBody& entry : lesson.editableBodies) {
        if (entry.body.index >= world.bodies.size() || entry.attributes.none())
            continue;
        OrderedJson item = OrderedJson::object();
        item["body"] = world.body(entry.body).name;
        item["attributes"] = namesJson(entry.attributes, kBodyAttributes);
        editable.push_back(std::move(item));
    }
    out["editable"] = std::move(editable);
    out["editableWorld"] = namesJson(lesson.editableWorld, kWorldAttributes);
    out["editableSprings"] = indexedJson(lesson.editableSprings, world.springs.size(), "spring", kSpringAttributes,
                                         &EditableSpring::spring);
    out["editableJoints"] =
        indexedJson(lesson.editableJoints, world.joints.size(), "joint", kJointAttributes, &EditableJoint::joint);
    OrderedJson questions = OrderedJson::array();
    for (const LessonQuestion& question : lesson.questions) {
        OrderedJson item = OrderedJson::object();
        item["prompt"] = question.prompt;
        item["answer"] = question.answer;
        item["unit"] = question.unit;
        item["tolerance"] = question.tolerance;
        questions.push_back(std::move(item));
    }
    out["questions"] = std::move(questions);
    return out;
}

} // namespace impetus::model
