#pragma once
// Installs the studio's translation and Qt's own (qtbase: standard dialogs and buttons) for a
// language. The studio's .qm files are compiled into the binary under :/i18n; Qt's come from
// QLibraryInfo::TranslationsPath (Debian: qt6-translations-l10n).
#include <QString>

namespace lipsync::studio {

class Translations
{
public:
    // `language` like "de" or "de_DE"; empty means the system locale. Replaces translators
    // installed by an earlier call. Returns true if the studio has a translation for it
    // (English, the source language, needs none and also returns true).
    static bool install(const QString &language = {});
    // Removes what install() put in place (back to English).
    static void remove();
};

} // namespace lipsync::studio
