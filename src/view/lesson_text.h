#pragma once
/// \file lesson_text.h
/// How the lesson's parts read in the window: attribute names in the user's language, and numbers
/// typed and shown in the user's locale.

#include "model/lesson.h"

#include <QLocale>
#include <QString>

#include <optional>

namespace impetus::view {

/// The translated name of a body attribute, in lower case for use inside a sentence ("friction",
/// "angular velocity").
QString attributeTitle(model::BodyAttribute attribute);

/// The translated name of a world setting, in lower case ("gravity", "time step").
QString attributeTitle(model::WorldAttribute attribute);

/// The translated name of a spring attribute, in lower case ("stiffness", "rest length").
QString attributeTitle(model::SpringAttribute attribute);

/// The translated name of a joint attribute, in lower case ("anchors").
QString attributeTitle(model::JointAttribute attribute);

/// The names of the attributes in `attributes`, in the scene format's order, joined by ", ".
QString attributeList(const model::BodyAttributes& attributes);
/// The names of the spring attributes in `attributes`, joined by ", " (SpringAttributes and
/// WorldAttributes are the same bitset type, hence its own name).
QString springAttributeList(const model::SpringAttributes& attributes);
/// The names of the joint attributes in `attributes`, joined by ", ".
QString jointAttributeList(const model::JointAttributes& attributes);
/// The names of the world settings in `attributes`, joined by ", ".
QString attributeList(const model::WorldAttributes& attributes);

/// `text` as a number: in `locale`'s format (a decimal comma in German), or else with a decimal
/// point, which scene files and textbooks use. Group separators are refused ("1,234" would mean
/// two different numbers in English and German). nullopt when it is not a finite number.
std::optional<double> parseLessonNumber(const QLocale& locale, const QString& text);

/// `value` in `locale`'s format with up to `digits` significant digits.
QString formatLessonNumber(const QLocale& locale, double value, int digits);

/// `number` (already formatted) followed by `unit`: "26.6°" for degrees, "2.95 s", or the number
/// alone when there is no unit.
QString withUnit(const QString& number, const QString& unit);

} // namespace impetus::view
