#include "view/lesson_text.h"

#include <QCoreApplication>
#include <QStringList>

#include <cmath>

namespace impetus::view {

QString attributeTitle(model::BodyAttribute attribute)
{
    switch (attribute) {
    case model::BodyAttribute::Name:
        return QCoreApplication::translate("impetus::view::LessonText", "name");
    case model::BodyAttribute::ShapeSize:
        return QCoreApplication::translate("impetus::view::LessonText", "size");
    case model::BodyAttribute::Position:
        return QCoreApplication::translate("impetus::view::LessonText", "position");
    case model::BodyAttribute::Angle:
        return QCoreApplication::translate("impetus::view::LessonText", "angle");
    case model::BodyAttribute::Velocity:
        return QCoreApplication::translate("impetus::view::LessonText", "velocity");
    case model::BodyAttribute::AngularVelocity:
        return QCoreApplication::translate("impetus::view::LessonText", "angular velocity");
    case model::BodyAttribute::Mass:
        return QCoreApplication::translate("impetus::view::LessonText", "mass");
    case model::BodyAttribute::Restitution:
        return QCoreApplication::translate("impetus::view::LessonText", "restitution");
    case model::BodyAttribute::Friction:
        return QCoreApplication::translate("impetus::view::LessonText", "friction");
    case model::BodyAttribute::Fixed:
        return QCoreApplication::translate("impetus::view::LessonText", "fixed");
    case model::BodyAttribute::FillColor:
        return QCoreApplication::translate("impetus::view::LessonText", "colour");
    case model::BodyAttribute::Soft:
        return QCoreApplication::translate("impetus::view::LessonText", "soft mode");
    }
    return {};
}

QString attributeTitle(model::WorldAttribute attribute)
{
    switch (attribute) {
    case model::WorldAttribute::Gravity:
        return QCoreApplication::translate("impetus::view::LessonText", "gravity");
    case model::WorldAttribute::Integrator:
        return QCoreApplication::translate("impetus::view::LessonText", "integrator");
    case model::WorldAttribute::TimeStep:
        return QCoreApplication::translate("impetus::view::LessonText", "time step");
    case model::WorldAttribute::Drag:
        return QCoreApplication::translate("impetus::view::LessonText", "drag");
    }
    return {};
}

QString attributeTitle(model::SpringAttribute attribute)
{
    switch (attribute) {
    case model::SpringAttribute::Stiffness:
        return QCoreApplication::translate("impetus::view::LessonText", "stiffness");
    case model::SpringAttribute::Damping:
        return QCoreApplication::translate("impetus::view::LessonText", "damping");
    case model::SpringAttribute::RestLength:
        return QCoreApplication::translate("impetus::view::LessonText", "rest length");
    case model::SpringAttribute::Anchors:
        return QCoreApplication::translate("impetus::view::LessonText", "anchors");
    }
    return {};
}

QString attributeTitle(model::JointAttribute attribute)
{
    switch (attribute) {
    case model::JointAttribute::Anchors:
        return QCoreApplication::translate("impetus::view::LessonText", "anchors");
    }
    return {};
}

namespace {

/// The titles of the attributes of `all` that are in `attributes`, in that order, joined by ", ".
template <class Attribute, std::size_t N>
QString joinedTitles(const std::bitset<N>& attributes, const std::array<Attribute, N>& all)
{
    QStringList names;
    for (const Attribute attribute : all) {
        if (attributes.test(static_cast<std::size_t>(attribute)))
            names << attributeTitle(attribute);
    }
    return names.join(QStringLiteral(", "));
}

} // namespace

QString springAttributeList(const model::SpringAttributes& attributes)
{
    return joinedTitles(attributes, model::kSpringAttributes);
}

QString jointAttributeList(const model::JointAttributes& attributes)
{
    return joinedTitles(attributes, model::kJointAttributes);
}

QString attributeList(const model::BodyAttributes& attributes) { return joinedTitles(attributes, model::kBodyAttributes); }

QString attributeList(const model::WorldAttributes& attributes) { return joinedTitles(attributes, model::kWorldAttributes); }

std::optional<double> parseLessonNumber(const QLocale& locale, const QString& text)
{
    const QString trimmed = text.trimmed();
    QLocale strict = locale;
    strict.setNumberOptions(QLocale::RejectGroupSeparator);
    bool ok = false;
    double value = strict.toDouble(trimmed, &ok);
    if (!ok) {
        QLocale c = QLocale::c();
        c.setNumberOptions(QLocale::RejectGroupSeparator);
        value = c.toDouble(trimmed, &ok);
    }
    if (!ok || !std::isfinite(value))
        return std::nullopt;
    return value;
}

QString formatLessonNumber(const QLocale& locale, double value, int digits)
{
    QLocale plain = locale;
    plain.setNumberOptions(QLocale::OmitGroupSeparator);
    return plain.toString(value, 'g', digits);
}

QString withUnit(const QString& number, const QString& unit)
{
    if (unit.isEmpty())
        return number;
    // Degrees follow the number directly (26.6°); every other unit after a space (2.95 s).
    if (unit == QStringLiteral("°"))
        return number + unit;
    return number + QLatin1Char(' ') + unit;
}

} // namespace impetus::view
