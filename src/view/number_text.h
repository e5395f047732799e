#pragma once
/// \file number_text.h
/// Numbers as the window's readouts write them: in the window's number format.

#include <QLocale>
#include <QString>

namespace impetus::view {

/// `value` as QLocale().toString(value, format, precision) writes it in the window's number format
/// ("0,25" in German), but with a small e before an exponent in every language ("1.5e-07"): QLocale
/// writes the locale's own sign, a capital E in English and German, where the readouts have always
/// written e (and the tests read it so).
inline QString localeNumber(double value, char format, int precision)
{
    const QLocale locale;
    return locale.toString(value, format, precision).replace(locale.exponential(), QStringLiteral("e"));
}

} // namespace impetus::view
