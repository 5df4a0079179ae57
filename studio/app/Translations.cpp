#include "app/Translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace lipsync::studio {

namespace {
QTranslator *g_studio = nullptr;
QTranslator *g_qt = nullptr;
} // namespace

void Translations::remove()
{
    for (QTranslator **t : {&g_studio, &g_qt}) {
        if (*t) {
            QCoreApplication::removeTranslator(*t);
            delete *t;
            *t = nullptr;
        }
    }
}

bool Translations::install(const QString &language)
{
    remove();
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    if (!language.isEmpty())
        QLocale::setDefault(locale);
    if (locale.language() == QLocale::English || locale.language() == QLocale::C)
        return true;

    g_studio = new QTranslator(QCoreApplication::instance());
    const bool ok = g_studio->load(locale, QStringLiteral("lipsync"), QStringLiteral("_"), QStringLiteral(":/i18n"));
    if (ok)
        QCoreApplication::installTranslator(g_studio);
    g_qt = new QTranslator(QCoreApplication::instance());
    if (g_qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                   QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(g_qt);
    return ok;
}

} // namespace lipsync::studio
