// Architecture rule as a test (after QGIS's test_banned_keywords.sh): core/ never includes QtGui
// or QtWidgets, so every algorithm stays usable headless by the CLI.
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QTest>

static const QRegularExpression &bannedInclude()
{
    static const QRegularExpression banned(QStringLiteral(
        R"(^\s*#\s*include\s*[<"](QtGui|QtWidgets|QtOpenGL|QtMultimedia)(/|>|")|)"
        R"(^\s*#\s*include\s*[<"](QWidget|QPainter|QImage|QPixmap|QApplication|QGuiApplication|QColor|QUndoStack|QUndoCommand)[>"])"),
        QRegularExpression::MultilineOption);
    return banned;
}

class TestCoreLayout : public QObject
{
    Q_OBJECT
private slots:
    void coreHasNoGuiIncludes()
    {
        const QRegularExpression &banned = bannedInclude();
        QDirIterator it(QStringLiteral(LIPSYNC_SOURCE_DIR "/core"),
                        {QStringLiteral("*.h"), QStringLiteral("*.cpp"), QStringLiteral("*.txt")},
                        QDir::Files, QDirIterator::Subdirectories);
        QStringList offenders;
        int files = 0;
        while (it.hasNext()) {
            const QString path = it.next();
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QString text = QString::fromUtf8(f.readAll());
            ++files;
            if (banned.match(text).hasMatch())
                offenders << path;
            if (path.endsWith(QLatin1String("CMakeLists.txt"))
                && text.contains(QRegularExpression(QStringLiteral("Qt6::(Gui|Widgets|OpenGL|Multimedia)"))))
                offenders << path;
        }
        QVERIFY2(files > 10, "core/ sources not found");
        QVERIFY2(offenders.isEmpty(), qPrintable(offenders.join(QLatin1Char('\n'))));
    }

    void bannedPatternDetectsGuiInclude()
    {
        // Guard against a pattern that silently matches nothing.
        const QRegularExpression &banned = bannedInclude();
        QVERIFY(banned.match(QStringLiteral("#include <QtWidgets/QWidget>")).hasMatch());
        QVERIFY(banned.match(QStringLiteral("  #  include <QtGui>")).hasMatch());
        QVERIFY(banned.match(QStringLiteral("#include \"QPainter\"")).hasMatch());
        QVERIFY(!banned.match(QStringLiteral("#include <QtCore/QString>")).hasMatch());
        QVERIFY(!banned.match(QStringLiteral("#include <QImageReaderless>")).hasMatch());
    }
};

QTEST_GUILESS_MAIN(TestCoreLayout)
#include "tst_corelayout.moc"
