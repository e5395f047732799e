#include "view/lesson_session.h"

#include "view/lesson_text.h"
#include "view/scene_document.h"

#include <array>
#include <bitset>

namespace impetus::view {

namespace {

/// The first of `lock`'s answers for the attributes of `all` that are in `changed` (in that
/// order), or nullopt when none of them is locked.
template <class Attribute, std::size_t N, class Lock>
std::optional<QString> firstLock(const std::bitset<N>& changed, const std::array<Attribute, N>& all, Lock lock)
{
    for (const Attribute attribute : all) {
        if (!changed.test(static_cast<std::size_t>(attribute)))
            continue;
        if (std::optional<QString> reason = lock(attribute))
            return reason;
    }
    return std::nullopt;
}

} // namespace

LessonSession::LessonSession(SceneDocument& document, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_lastLesson(document.world().lesson)
{
    connect(&m_document, &SceneDocument::worldChanged, this, &LessonSession::onWorldChanged);
    // A scene opened anew comes with its locks in force, whoever turned Lesson › Edit on before.
    connect(&m_document, &SceneDocument::sceneReplaced, this, [this] { setEditing(false); });
}

const std::optional<model::Lesson>& LessonSession::lesson() const { return m_document.world().lesson; }

void LessonSession::setEditing(bool on)
{
    if (on == m_editing)
        return;
    m_editing = on;
    emit editingChanged(on);
    emit locksChanged();
}

bool LessonSession::locksInForce() const { return lesson().has_value() && !m_editing; }

void LessonSession::onWorldChanged()
{
    // Most world changes are edits of bodies; only a lesson that changed changes the locks.
    if (lesson() == m_lastLesson)
        return;
    m_lastLesson = lesson();
    emit locksChanged();
}

QString LessonSession::bodyName(int body) const
{
    const model::World& world = m_document.world();
    if (body < 0 || static_cast<std::size_t>(body) >= world.bodies.size())
        return {};
    return QString::fromStdString(world.bodies[static_cast<std::size_t>(body)].name);
}

std::optional<QString> LessonSession::bodyLock(int body, model::BodyAttribute attribute) const
{
    if (!locksInForce() || (body >= 0 && lesson()->allows(model::BodyId{static_cast<std::uint32_t>(body)}, attribute)))
        return std::nullopt;
    return tr("Locked by the lesson: the %1 of “%2” can't be changed.").arg(attributeTitle(attribute), bodyName(body));
}

std::optional<QString> LessonSession::worldLock(model::WorldAttribute attribute) const
{
    if (!locksInForce() || lesson()->allows(attribute))
        return std::nullopt;
    return tr("Locked by the lesson: the %1 can't be changed.").arg(attributeTitle(attribute));
}

std::optional<QString> LessonSession::refusal(int body, const model::Body& before, const model::Body& after) const
{
    model::BodyAttributes changed = model::changedAttributes(before, after);
    // A polygon's new vertices move its centroid, which is the body's position: a lesson that
    // lets its shape change lets it move that much.
    if (changed.test(static_cast<std::size_t>(model::BodyAttribute::ShapeSize)))
        changed.reset(static_cast<std::size_t>(model::BodyAttribute::Position));
    return firstLock(changed, model::kBodyAttributes,
                     [&](model::BodyAttribute attribute) { return bodyLock(body, attribute); });
}

std::optional<QString> LessonSession::refusal(const model::WorldSettings& before,
                                              const model::WorldSettings& after) const
{
    return firstLock(model::changedAttributes(before, after), model::kWorldAttributes,
                     [&](model::WorldAttribute attribute) { return worldLock(attribute); });
}

bool LessonSession::isPin(int joint) const
{
    const model::World& world = m_document.world();
    return joint >= 0 && static_cast<std::size_t>(joint) < world.joints.size() &&
           world.joints[static_cast<std::size_t>(joint)].type == model::JointType::Pin;
}

std::optional<QString> LessonSession::jointLock(int joint, model::JointAttribute attribute) const
{
    if (!locksInForce() || (joint >= 0 && lesson()->allows(static_cast<std::size_t>(joint), attribute)))
        return std::nullopt;
    // A pin's anchors are its hinge, as its page calls them.
    const QString what = isPin(joint) ? tr("hinge") : attributeTitle(attribute);
    return tr("Locked by the lesson: the %1 of joint %2 can't be changed.").arg(what).arg(joint);
}

std::optional<QString> LessonSession::refusal(int joint, const model::Joint& before, const model::Joint& after) const
{
    if (locksInForce() && model::changesEnds(before, after))
        return tr("Locked by the lesson: joint %1 can't be changed to another type or to other bodies.").arg(joint);
    return firstLock(model::changedAttributes(before, after), model::kJointAttributes,
                     [&](model::JointAttribute attribute) { return jointLock(joint, attribute); });
}

std::optional<QString> LessonSession::springLock(int spring, model::SpringAttribute attribute) const
{
    if (!locksInForce() || (spring >= 0 && lesson()->allows(static_cast<std::size_t>(spring), attribute)))
        return std::nullopt;
    return tr("Locked by the lesson: the %1 of spring %2 can't be changed.").arg(attributeTitle(attribute)).arg(spring);
}

std::optional<QString> LessonSession::refusal(int spring, const model::Spring& before, const model::Spring& after) const
{
    if (locksInForce() && model::changesEnds(before, after))
        return tr("Locked by the lesson: spring %1 can't be joined to other bodies.").arg(spring);
    return firstLock(model::changedAttributes(before, after), model::kSpringAttributes,
                     [&](model::SpringAttribute attribute) { return springLock(spring, attribute); });
}

std::optional<QString> LessonSession::springNote(int spring) const
{
    if (!locksInForce() || spring < 0)
        return std::nullopt;
    const model::SpringAttributes editable = lesson()->editableSpring(static_cast<std::size_t>(spring));
    if (editable.none())
        return tr("Locked by the lesson: this spring can't be changed.");
    return tr("Locked by the lesson. You may change its %1.").arg(springAttributeList(editable));
}

std::optional<QString> LessonSession::jointNote(int joint) const
{
    if (!locksInForce() || joint < 0)
        return std::nullopt;
    const model::JointAttributes editable = lesson()->editableJoint(static_cast<std::size_t>(joint));
    if (editable.none())
        return tr("Locked by the lesson: this joint can't be changed.");
    return tr("Locked by the lesson. You may change its %1.").arg(isPin(joint) ? tr("hinge") : jointAttributeList(editable));
}

std::optional<QString> LessonSession::poseLock(const std::vector<int>& bodies, bool moves, bool turns) const
{
    // Several bodies turn about their common centre, so each of them moves too.
    const bool needsPosition = moves || (turns && bodies.size() > 1);
    for (const int body : bodies) {
        if (needsPosition && bodyLock(body, model::BodyAttribute::Position))
            return turns ? tr("Locked by the lesson: “%1” can't be turned.").arg(bodyName(body))
                         : tr("Locked by the lesson: “%1” can't be moved.").arg(bodyName(body));
        if (turns && bodyLock(body, model::BodyAttribute::Angle))
            return tr("Locked by the lesson: “%1” can't be turned.").arg(bodyName(body));
    }
    return std::nullopt;
}

std::optional<QString> LessonSession::removalLock(const Selection& selection) const
{
    if (!locksInForce() || selection.empty())
        return std::nullopt;
    return tr("Locked by the lesson: nothing can be deleted.");
}

std::optional<QString> LessonSession::drawingLock() const
{
    if (!locksInForce())
        return std::nullopt;
    return tr("Locked by the lesson: new bodies, springs and joints can't be added.");
}

std::optional<QString> LessonSession::bodyNote(int body) const
{
    if (!locksInForce() || body < 0)
        return std::nullopt;
    const model::BodyAttributes editable = lesson()->editable(model::BodyId{static_cast<std::uint32_t>(body)});
    if (editable.none())
        return tr("Locked by the lesson: this body can't be changed.");
    return tr("Locked by the lesson. You may change its %1.").arg(attributeList(editable));
}

std::optional<QString> LessonSession::worldNote() const
{
    if (!locksInForce())
        return std::nullopt;
    if (lesson()->editableWorld.none())
        return tr("Locked by the lesson: the world settings can't be changed.");
    return tr("Locked by the lesson. You may change the %1.").arg(attributeList(lesson()->editableWorld));
}

std::optional<QString> poseLockOf(const LessonSession* session, const std::vector<int>& bodies, bool moves, bool turns)
{
    return session ? session->poseLock(bodies, moves, turns) : std::nullopt;
}

} // namespace impetus::view
