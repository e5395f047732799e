#pragma once
/// \file lesson.h
/// A lesson: what a teacher adds to a scene to make it an exercise (scene key `lesson`, an
/// addition to the contract described in docs/scene-format.md). It names the few things students
/// may change, and every other attribute of the scene is locked; it asks questions with numeric
/// answers that the app checks. The engine ignores it: it changes nothing in how the scene moves.

#include "model/body.h"
#include "model/joint.h"
#include "model/scalar.h"
#include "model/spring.h"

#include <array>
#include <bitset>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impetus::model {

struct WorldSettings;

/// What of a body a lesson may leave editable. Each is one or more scene keys of the body.
enum class BodyAttribute {
    Name, ///< "name"
    ShapeSize, ///< "shape": its sizes or vertices (its type stays)
    Position, ///< "position": also moving it on the canvas
    Angle, ///< "angle": also turning it on the canvas
    Velocity, ///< "velocity"
    AngularVelocity, ///< "angularVelocity"
    Mass, ///< "mass": the mass or the density, and which of the two is given
    Restitution, ///< "restitution"
    Friction, ///< "friction"
    Fixed, ///< "fixed"
    FillColor, ///< "color"
    Soft, ///< "soft": soft mode on or off and its settings
};

/// The number of BodyAttribute values.
inline constexpr std::size_t kBodyAttributeCount = 12;

/// Every BodyAttribute, in the order the scene format lists a body's keys.
inline constexpr std::array<BodyAttribute, kBodyAttributeCount> kBodyAttributes = {
    BodyAttribute::Name,        BodyAttribute::ShapeSize,       BodyAttribute::Position, BodyAttribute::Angle,
    BodyAttribute::Velocity,    BodyAttribute::AngularVelocity, BodyAttribute::Mass, BodyAttribute::Restitution,
    BodyAttribute::Friction,    BodyAttribute::Fixed,       BodyAttribute::FillColor,    BodyAttribute::Soft};

/// What of the world settings a lesson may leave editable (keys of the scene's `world`).
enum class WorldAttribute {
    Gravity, ///< "gravity"
    Integrator, ///< "integrator"
    TimeStep, ///< "timeStep"
    Drag, ///< "drag"
};

/// The number of WorldAttribute values.
inline constexpr std::size_t kWorldAttributeCount = 4;

/// Every WorldAttribute, in the order of the scene's `world` keys.
inline constexpr std::array<WorldAttribute, kWorldAttributeCount> kWorldAttributes = {
    WorldAttribute::Gravity, WorldAttribute::Integrator, WorldAttribute::TimeStep, WorldAttribute::Drag};

/// What of a spring a lesson may leave editable (keys of a scene's spring).
enum class SpringAttribute {
    Stiffness, ///< "stiffness"
    Damping, ///< "damping"
    RestLength, ///< "restLength"
    Anchors, ///< "anchors": anchorA and anchorB, where the spring is fixed on its bodies
};

/// The number of SpringAttribute values.
inline constexpr std::size_t kSpringAttributeCount = 4;

/// Every SpringAttribute, in the order of a spring's keys in the scene format.
inline constexpr std::array<SpringAttribute, kSpringAttributeCount> kSpringAttributes = {
    SpringAttribute::Stiffness, SpringAttribute::Damping, SpringAttribute::RestLength, SpringAttribute::Anchors};

/// What of a joint a lesson may leave editable. A joint's type and the bodies it joins never are.
enum class JointAttribute {
    Anchors, ///< "anchors": a pin's hinge (`anchor`), or a rod's two ends (`anchorA`, `anchorB`)
};

/// The number of JointAttribute values.
inline constexpr std::size_t kJointAttributeCount = 1;

/// Every JointAttribute.
inline constexpr std::array<JointAttribute, kJointAttributeCount> kJointAttributes = {JointAttribute::Anchors};

/// A set of body attributes, indexed by BodyAttribute.
using BodyAttributes = std::bitset<kBodyAttributeCount>;

/// A set of world attributes, indexed by WorldAttribute.
using WorldAttributes = std::bitset<kWorldAttributeCount>;

/// A set of spring attributes, indexed by SpringAttribute.
using SpringAttributes = std::bitset<kSpringAttributeCount>;

/// A set of joint attributes, indexed by JointAttribute.
using JointAttributes = std::bitset<kJointAttributeCount>;

/// The scene-file name of a body attribute ("friction", "angularVelocity", …).
std::string_view attributeName(BodyAttribute attribute);
/// The scene-file name of a world attribute ("gravity", "timeStep", …).
std::string_view attributeName(WorldAttribute attribute);
/// Parses a body attribute's scene-file name; nullopt when unknown.
std::optional<BodyAttribute> bodyAttributeFromName(std::string_view name);
/// Parses a world attribute's scene-file name; nullopt when unknown.
std::optional<WorldAttribute> worldAttributeFromName(std::string_view name);
/// The scene-file name of a spring attribute ("stiffness", "restLength", …).
std::string_view attributeName(SpringAttribute attribute);
/// Parses a spring attribute's scene-file name; nullopt when unknown.
std::optional<SpringAttribute> springAttributeFromName(std::string_view name);
/// The scene-file name of a joint attribute ("anchors").
std::string_view attributeName(JointAttribute attribute);
/// Parses a joint attribute's scene-file name; nullopt when unknown.
std::optional<JointAttribute> jointAttributeFromName(std::string_view name);

/// A body students may change, and which of its attributes.
struct EditableBody {
    BodyId body; ///< the body
    BodyAttributes attributes; ///< what of it students may change; never empty in a Lesson
    bool operator==(const EditableBody&) const = default; ///< memberwise equality
};

/// A spring students may change, and which of its attributes.
struct EditableSpring {
    std::size_t spring = 0; ///< index into World::springs
    SpringAttributes attributes; ///< what of it students may change; never empty in a Lesson
    bool operator==(const EditableSpring&) const = default; ///< memberwise equality
};

/// A joint students may change, and which of its attributes.
struct EditableJoint {
    std::size_t joint = 0; ///< index into World::joints
    JointAttributes attributes; ///< what of it students may change; never empty in a Lesson
    bool operator==(const EditableJoint&) const = default; ///< memberwise equality
};

/// A question with a numeric answer: right when the student's value v satisfies
/// |v − answer| ≤ tolerance, in `unit`.
struct LessonQuestion {
    std::string prompt; ///< the question, e.g. "At what angle does the block start to slide?"
    Scalar answer = 0; ///< the right value, in `unit`
    std::string unit; ///< the unit of the answer, e.g. "°", "s", "kg·m/s"; empty for a pure number
    Scalar tolerance = 0; ///< the largest accepted |v − answer|, in `unit`, > 0
    bool operator==(const LessonQuestion&) const = default; ///< memberwise equality

    /// True when `value` (in `unit`) is within the tolerance of the answer.
    bool accepts(Scalar value) const;
};

/// A scene's lesson (scene key `lesson`). Everything a lesson does not list as editable is locked
/// for students: in the app, locked attributes cannot be changed, and locked bodies cannot be
/// moved, turned or deleted. A teacher lifts the locks to author the lesson.
struct Lesson {
    std::string title; ///< shown at the top of the lesson panel; non-empty
    std::string instructions; ///< plain text or simple Markdown, shown under the title
    /// The bodies students may change, sorted by body index, at most one entry per body, none
    /// with an empty attribute set.
    std::vector<EditableBody> editableBodies;
    WorldAttributes editableWorld; ///< the world settings students may change
    /// The springs students may change, sorted by spring index, at most one entry per spring, none
    /// with an empty attribute set. Springs not listed are locked.
    std::vector<EditableSpring> editableSprings;
    /// The joints students may change, sorted by joint index, at most one entry per joint, none
    /// with an empty attribute set. Joints not listed are locked.
    std::vector<EditableJoint> editableJoints;
    std::vector<LessonQuestion> questions; ///< in the order they are asked
    bool operator==(const Lesson&) const = default; ///< memberwise equality

    /// The attributes of body `body` that students may change (empty: the body is locked).
    BodyAttributes editable(BodyId body) const;
    /// True when students may change `attribute` of body `body`.
    bool allows(BodyId body, BodyAttribute attribute) const;
    /// True when students may change the world setting `attribute`.
    bool allows(WorldAttribute attribute) const;
    /// Makes `attributes` exactly what students may change of body `body`; an empty set locks it
    /// entirely. Keeps editableBodies sorted and free of empty entries.
    void setEditable(BodyId body, BodyAttributes attributes);

    /// Follows a removal of bodies: drops the entries of bodies for which `removed[index]` is
    /// true and renumbers the others as the bodies that stay close up. `removed` has one flag per
    /// body of the world before the removal.
    void removeBodies(const std::vector<bool>& removed);

    /// The attributes of spring `spring` that students may change (empty: the spring is locked).
    SpringAttributes editableSpring(std::size_t spring) const;
    /// True when students may change `attribute` of spring `spring`.
    bool allows(std::size_t spring, SpringAttribute attribute) const;
    /// Makes `attributes` exactly what students may change of spring `spring`; an empty set locks
    /// it. Keeps editableSprings sorted and free of empty entries.
    void setEditableSpring(std::size_t spring, SpringAttributes attributes);
    /// Follows a removal of springs, as removeBodies() does for bodies: `removed` has one flag per
    /// spring of the world before the removal.
    void removeSprings(const std::vector<bool>& removed);

    /// The attributes of joint `joint` that students may change (empty: the joint is locked).
    JointAttributes editableJoint(std::size_t joint) const;
    /// True when students may change `attribute` of joint `joint`.
    bool allows(std::size_t joint, JointAttribute attribute) const;
    /// Makes `attributes` exactly what students may change of joint `joint`; an empty set locks
    /// it. Keeps editableJoints sorted and free of empty entries.
    void setEditableJoint(std::size_t joint, JointAttributes attributes);
    /// Follows a removal of joints, as removeSprings() does for springs.
    void removeJoints(const std::vector<bool>& removed);
};

/// The attributes in which `after` differs from `before`: what an edit of a body changes.
/// Derived fields and the collision state are not attributes; a change of the mass mode (mass or
/// density given) counts as Mass.
BodyAttributes changedAttributes(const Body& before, const Body& after);

/// The world settings in which `after` differs from `before`.
WorldAttributes changedAttributes(const WorldSettings& before, const WorldSettings& after);

/// The attributes in which spring `after` differs from `before`. Its bodies are not an attribute:
/// a spring moved to other bodies is `changesEnds`.
SpringAttributes changedAttributes(const Spring& before, const Spring& after);

/// True when `after` joins other bodies than `before` (which no lesson leaves editable).
bool changesEnds(const Spring& before, const Spring& after);

/// The attributes in which joint `after` differs from `before`: its anchors, a pin's hinge and
/// the anchors derived from it included. Its type, its bodies and the solver's impulse are not
/// attributes (see changesEnds).
JointAttributes changedAttributes(const Joint& before, const Joint& after);

/// True when `after` is of another type than `before` or joins other bodies (which no lesson
/// leaves editable).
bool changesEnds(const Joint& before, const Joint& after);

} // namespace impetus::model
