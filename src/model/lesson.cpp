#include "model/lesson.h"

#include "model/world.h"

#include <algorithm>
#include <functional>
#include <cmath>

namespace impetus::model {

namespace {

/// Scene-file names, indexed like the enums.
constexpr std::array<std::string_view, kBodyAttributeCount> kBodyAttributeNames = {
    "name",     "shape",       "position", "angle", "velocity", "angularVelocity",
    "mass",     "restitution", "friction", "fixed", "color",    "soft"};
constexpr std::array<std::string_view, kWorldAttributeCount> kWorldAttributeNames = {"gravity", "integrator",
                                                                                     "timeStep", "drag"};

constexpr std::array<std::string_view, kSpringAttributeCount> kSpringAttributeNames = {"stiffness", "damping",
                                                                                       "restLength", "anchors"};
constexpr std::array<std::string_view, kJointAttributeCount> kJointAttributeNames = {"anchors"};

template <class Attribute, std::size_t N>
std::optional<Attribute> fromName(std::string_view name, const std::array<std::string_view, N>& names)
{
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
        return std::nullopt;
    return static_cast<Attribute>(it - names.begin());
}

/// Makes `attributes` exactly the set of the entry for `key` in `entries` (sorted by `key`): an
/// empty set removes the entry. EditableBody and EditableSpring alike.
template <class Entry, class Key, class Attributes, class KeyOf>
void setEntry(std::vector<Entry>& entries, Key key, Attributes attributes, KeyOf keyOf)
{
    const auto it = std::ranges::lower_bound(entries, key, {}, keyOf);
    const bool present = it != entries.end() && std::invoke(keyOf, *it) == key;
    if (attributes.none()) {
        if (present)
            entries.erase(it);
    } else if (present) {
        it->attributes = attributes;
    } else {
        entries.insert(it, Entry{key, attributes});
    }
}

/// An entry's index moved down by `below` places.
void renumber(EditableBody& entry, std::size_t below) { entry.body.index -= static_cast<std::uint32_t>(below); }
void renumber(EditableSpring& entry, std::size_t below) { entry.spring -= below; }
void renumber(EditableJoint& entry, std::size_t below) { entry.joint -= below; }

/// Drops the entries whose index `indexOf` is flagged in `removed` and renumbers the rest as
/// the items that stay close up.
template <class Entry, class IndexOf>
void removeEntries(std::vector<Entry>& entries, const std::vector<bool>& removed, IndexOf indexOf)
{
    std::erase_if(entries, [&](const Entry& entry) {
        const std::size_t index = indexOf(entry);
        return index >= removed.size() || removed[index];
    });
    for (Entry& entry : entries) {
        const auto below = std::count(removed.begin(), removed.begin() + static_cast<std::ptrdiff_t>(indexOf(entry)), true);
        renumber(entry, static_cast<std::size_t>(below));
    }
}


} // namespace

std::string_view attributeName(BodyAttribute attribute) { return kBodyAttributeNames[static_cast<std::size_t>(attribute)]; }

std::string_view attributeName(WorldAttribute attribute)
{
    return kWorldAttributeNames[static_cast<std::size_t>(attribute)];
}

std::optional<BodyAttribute> bodyAttributeFromName(std::string_view name)
{
    return fromName<BodyAttribute>(name, kBodyAttributeNames);
}

std::optional<WorldAttribute> worldAttributeFromName(std::string_view name)
{
    return fromName<WorldAttribute>(name, kWorldAttributeNames);
}

std::string_view attributeName(SpringAttribute attribute)
{
    return kSpringAttributeNames[static_cast<std::size_t>(attribute)];
}

std::optional<SpringAttribute> springAttributeFromName(std::string_view name)
{
    return fromName<SpringAttribute>(name, kSpringAttributeNames);
}

std::string_view attributeName(JointAttribute attribute)
{
    return kJointAttributeNames[static_cast<std::size_t>(attribute)];
}

std::optional<JointAttribute> jointAttributeFromName(std::string_view name)
{
    return fromName<JointAttribute>(name, kJointAttributeNames);
}

bool LessonQuestion::accepts(Scalar value) const
{
    // A NaN compares false and so is never right.
    return std::isfinite(value) && std::abs(value - answer) <= tolerance;
}

BodyAttributes Lesson::editable(BodyId body) const
{
    const auto it = std::ranges::find(editableBodies, body, &EditableBody::body);
    return it == editableBodies.end() ? BodyAttributes() : it->attributes;
}

bool Lesson::allows(BodyId body, BodyAttribute attribute) const
{
    return editable(body).test(static_cast<std::size_t>(attribute));
}

bool Lesson::allows(WorldAttribute attribute) const { return editableWorld.test(static_cast<std::size_t>(attribute)); }

void Lesson::setEditable(BodyId body, BodyAttributes attributes)
{
    setEntry(editableBodies, body, attributes, &EditableBody::body);
}

void Lesson::removeBodies(const std::vector<bool>& removed)
{
    removeEntries(editableBodies, removed, [](const EditableBody& entry) { return std::size_t{entry.body.index}; });
}

SpringAttributes Lesson::editableSpring(std::size_t spring) const
{
    const auto it = std::ranges::find(editableSprings, spring, &EditableSpring::spring);
    return it == editableSprings.end() ? SpringAttributes() : it->attributes;
}

bool Lesson::allows(std::size_t spring, SpringAttribute attribute) const
{
    return editableSpring(spring).test(static_cast<std::size_t>(attribute));
}

void Lesson::setEditableSpring(std::size_t spring, SpringAttributes attributes)
{
    setEntry(editableSprings, spring, attributes, &EditableSpring::spring);
}

void Lesson::removeSprings(const std::vector<bool>& removed)
{
    removeEntries(editableSprings, removed, [](const EditableSpring& entry) { return entry.spring; });
}

JointAttributes Lesson::editableJoint(std::size_t joint) const
{
    const auto it = std::ranges::find(editableJoints, joint, &EditableJoint::joint);
    return it == editableJoints.end() ? JointAttributes() : it->attributes;
}

bool Lesson::allows(std::size_t joint, JointAttribute attribute) const
{
    return editableJoint(joint).test(static_cast<std::size_t>(attribute));
}

void Lesson::setEditableJoint(std::size_t joint, JointAttributes attributes)
{
    setEntry(editableJoints, joint, attributes, &EditableJoint::joint);
}

void Lesson::removeJoints(const std::vector<bool>& removed)
{
    removeEntries(editableJoints, removed, [](const EditableJoint& entry) { return entry.joint; });
}

BodyAttributes changedAttributes(const Body& before, const Body& after)
{
    BodyAttributes changed;
    const auto mark = [&changed](BodyAttribute attribute, bool differs) {
        if (differs)
            changed.set(static_cast<std::size_t>(attribute));
    };
    mark(BodyAttribute::Name, before.name != after.name);
    mark(BodyAttribute::ShapeSize, before.shape != after.shape);
    mark(BodyAttribute::Position, before.state.position != after.state.position);
    mark(BodyAttribute::Angle, before.state.angle != after.state.angle);
    mark(BodyAttribute::Velocity, before.state.velocity != after.state.velocity);
    mark(BodyAttribute::AngularVelocity, before.state.angularVelocity != after.state.angularVelocity);
    mark(BodyAttribute::Mass, before.massSpec != after.massSpec);
    mark(BodyAttribute::Restitution, before.material.restitution != after.material.restitution);
    mark(BodyAttribute::Friction, before.material.friction != after.material.friction);
    mark(BodyAttribute::Fixed, before.fixed != after.fixed);
    mark(BodyAttribute::FillColor, before.color != after.color);
    mark(BodyAttribute::Soft, before.soft != after.soft);
    return changed;
}

WorldAttributes changedAttributes(const WorldSettings& before, const WorldSettings& after)
{
    WorldAttributes changed;
    changed.set(static_cast<std::size_t>(WorldAttribute::Gravity), before.gravity != after.gravity);
    changed.set(static_cast<std::size_t>(WorldAttribute::Integrator), before.integrator != after.integrator);
    changed.set(static_cast<std::size_t>(WorldAttribute::TimeStep), before.timeStep != after.timeStep);
    changed.set(static_cast<std::size_t>(WorldAttribute::Drag), before.drag != after.drag);
    return changed;
}

SpringAttributes changedAttributes(const Spring& before, const Spring& after)
{
    SpringAttributes changed;
    changed.set(static_cast<std::size_t>(SpringAttribute::Stiffness), before.stiffness != after.stiffness);
    changed.set(static_cast<std::size_t>(SpringAttribute::Damping), before.damping != after.damping);
    changed.set(static_cast<std::size_t>(SpringAttribute::RestLength), before.restLength != after.restLength);
    changed.set(static_cast<std::size_t>(SpringAttribute::Anchors),
                before.anchorA != after.anchorA || before.anchorB != after.anchorB);
    return changed;
}

bool changesEnds(const Spring& before, const Spring& after)
{
    return before.bodyA != after.bodyA || before.bodyB != after.bodyB;
}

JointAttributes changedAttributes(const Joint& before, const Joint& after)
{
    JointAttributes changed;
    changed.set(static_cast<std::size_t>(JointAttribute::Anchors), before.worldAnchor != after.worldAnchor ||
                                                                       before.anchorA != after.anchorA ||
                                                                       before.anchorB != after.anchorB ||
                                                                       before.length != after.length);
    return changed;
}

bool changesEnds(const Joint& before, const Joint& after)
{
    return before.type != after.type || before.bodyA != after.bodyA || before.bodyB != after.bodyB;
}

} // namespace impetus::model
