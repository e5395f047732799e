#include "model/lesson.h"

#include "model/world.h"

#include <algorithm>
#include <cmath>

namespace impetus::model {

namespace {

/// Scene-file names, indexed like the enums.
constexpr std::array<std::string_view, kBodyAttributeCount> kBodyAttributeNames = {
    "name",     "shape",       "position", "angle", "velocity", "angularVelocity",
    "mass",     "restitution", "friction", "fixed", "color",    "soft"};
constexpr std::array<std::string_view, kWorldAttributeCount> kWorldAttributeNames = {"gravity", "integrator",
                                                                                     "timeStep", "drag"};

template <class Attribute, std::size_t N>
std::optional<Attribute> fromName(std::string_view name, const std::array<std::string_view, N>& names)
{
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
        return std::nullopt;
    return static_cast<Attribute>(it - names.begin());
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
    const auto it = std::ranges::lower_bound(editableBodies, body, {}, &EditableBody::body);
    const bool present = it != editableBodies.end() && it->body == body;
    if (attributes.none()) {
        if (present)
            editableBodies.erase(it);
    } else if (present) {
        it->attributes = attributes;
    } else {
        editableBodies.insert(it, EditableBody{body, attributes});
    }
}

void Lesson::removeBodies(const std::vector<bool>& removed)
{
    std::erase_if(editableBodies, [&](const EditableBody& entry) {
        return entry.body.index >= removed.size() || removed[entry.body.index];
    });
    for (EditableBody& entry : editableBodies) {
        const auto below = std::count(removed.begin(), removed.begin() + entry.body.index, true);
        entry.body.index -= static_cast<std::uint32_t>(below);
    }
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

} // namespace impetus::model
