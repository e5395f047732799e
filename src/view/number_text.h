#pragma once
/// \file number_text.h
/// Numbers as the window's readouts write them: in the window's number format.

#include <QLocale>
#include <QString>

namespace impetus::view {

/// `value` as locale.toString(value, format, precision) writes it in that number format
/// ("0,25" in German), but with a small e before an exponent in every language ("1.5e-07"): QLocale
/// writes the locale's own sign, a capital E in English and German, where the readouts have always
/// written e (and the tests read it so).
inline QString localeNumber(const QLocale& locale, double value, char format, int precision)
{
    return locale.toString(value, format, precision).replace(locale.exponential(), QStringLiteral("e"));
}

/// localeNumber in the window's locale, QLocale().
inline QString localeNumber(double value, char format, int precision)
{
    return localeNumber(QLocale(), value, format, precision);
}

} // namespace impetus::view
