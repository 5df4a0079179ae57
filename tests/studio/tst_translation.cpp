// The German translation is complete (no unfinished message in the .ts) and, once loaded,
// changes the main window's menus; English is back after removing it.
#include "DemoWindow.h"

#include "app/MainWindow.h"
#include "app/Translations.h"

#include <QFile>
#include <QMenuBar>
#include <QTest>

using namespace lipsync::studio;

namespace {

QString firstMenuTitle()
{
    MainWindow window;
    return window.menuBar()->actions().value(0) ? window.menuBar()->actions().value(0)->text() : QString();
}

} // namespace

class TestTranslation : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void germanTranslationIsComplete()
    {
        QFile ts(QStringLiteral(LIPSYNC_SOURCE_DIR "/translations/lipsync_de.ts"));
        QVERIFY(ts.open(QIODevice::ReadOnly));
        const QByteArray xml = ts.readAll();
        QVERIFY2(xml.count("<message") > 100, "the .ts holds fewer messages than the studio has");
        QCOMPARE(xml.count("type=\"unfinished\""), 0);
        QCOMPARE(xml.count("type=\"obsolete\""), 0);
        QCOMPARE(xml.count("type=\"vanished\""), 0);
    }

    void germanChangesTheMenus()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("lipsync-tests"));
        Translations::install(QStringLiteral("en"));
        QCOMPARE(firstMenuTitle(), QStringLiteral("&File"));
        QVERIFY(Translations::install(QStringLiteral("de")));
        QCOMPARE(firstMenuTitle(), QStringLiteral("&Datei"));
        // Qt's own translation (standard buttons) is loaded too.
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), QStringLiteral("Abbrechen"));
        Translations::remove();
        QCOMPARE(firstMenuTitle(), QStringLiteral("&File"));
    }
};

QTEST_MAIN(TestTranslation)
#include "tst_translation.moc"
