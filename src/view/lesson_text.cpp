#include "view/lesson_text.h"

#include <QCoreApplication>
#include <QStringList>

#include <cmath>

namespace impetus::view {

namespace {

QString translate(const char* text) { return QCoreApplication::translate("impetus::view::LessonText", text); }

} // namespace

QString attributeTitle(model::BodyAttribute attribute)
{
    switch (attribute) {
    case model::BodyAttribute::Name:
        return translate("name");
    case model::BodyAttribute::ShapeSize:
        return translate("size");
    case model::BodyAttribute::Position:
        return translate("position");
    case model::BodyAttribute::Angle:
        return translate("angle");
    case model::BodyAttribute::Velocity:
        return translate("velocity");
    case model::BodyAttribute::AngularVelocity:
        return translate("angular velocity");
    case model::BodyAttribute::Mass:
        return translate("mass");
    case model::BodyAttribute::Restitution:
        return translate("restitution");
    case model::BodyAttribute::Friction:
        return translate("friction");
    case model::BodyAttribute::Fixed:
        return translate("fixed");
    case model::BodyAttribute::FillColor:
        return translate("colour");
    case model::BodyAttribute::Soft:
        return translate("soft mode");
    }
    return {};
}

QString attributeTitle(model::WorldAttribute attribute)
{
    switch (attribute) {
    case model::WorldAttribute::Gravity:
        return translate("gravity");
    case model::WorldAttribute::Integrator:
        return translate("integrator");
    case model::WorldAttribute::TimeStep:
        return translate("time step");
    case model::WorldAttribute::Drag:
        return translate("drag");
    }
    return {};
}

QString attributeList(const model::BodyAttributes& attributes)
{
    QStringList names;
    for (const model::BodyAttribute attribute : model::kBodyAttributes) {
        if (attributes.test(static_cast<std::size_t>(attribute)))
            names << attributeTitle(attribute);
    }
    return names.join(QStringLiteral(", "));
}

QString attributeList(const model::WorldAttributes& attributes)
{
    QStringList names;
    for (const model::WorldAttribute attribute : model::kWorldAttributes) {
        if (attributes.test(static_cast<std::size_t>(attribute)))
            names << attributeTitle(attribute);
    }
    return names.join(QStringLiteral(", "));
}

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
