// Architecture rules as tests (after QGIS's test_banned_keywords.sh): core/ never includes QtGui
// or QtWidgets, so every algorithm stays usable headless by the CLI; each core module includes
// only the modules its CMakeLists.txt names as dependencies, which form no cycle, so every library
// links on its own and the layering is what the build files say; and the studio's folders, each a
// library of its own (lipsync_studio_layer), include only the layers they link, without a cycle:
// app/ (the window) on top, the panels' folders below it, context/ (StudioContext and what panels
// share) and document/ (the project document and its undo commands) at the bottom, so a panel
// builds with a context and no window.
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QMap>
#include <QRegularExpression>
#include <QSet>
#include <QTest>

namespace {

QString readText(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// Module -> the core modules its lipsync_core_module(NAME DEPS ...) names.
QMap<QString, QSet<QString>> declaredDependencies(const QString &core)
{
    QMap<QString, QSet<QString>> deps;
    const QRegularExpression call(QStringLiteral("lipsync_core_module\\(\\s*(\\w+)([^)]*)\\)"));
    const QRegularExpression lib(QStringLiteral("\\blipsync_(\\w+)"));
    for (const QString &module : QDir(core).entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        const auto m = call.match(readText(core + QLatin1Char('/') + module + QStringLiteral("/CMakeLists.txt")));
        if (!m.hasMatch())
            continue;
        QSet<QString> &d = deps[m.captured(1)];
        for (auto it = lib.globalMatch(m.captured(2)); it.hasNext();)
            d.insert(it.next().captured(1));
    }
    return deps;
}

// Studio folder -> the studio layers its lipsync_studio_layer(NAME DEPS ...) names
// (studio/CMakeLists.txt).
QMap<QString, QSet<QString>> declaredStudioLayers(const QString &studio)
{
    QMap<QString, QSet<QString>> deps;
    const QRegularExpression call(QStringLiteral("lipsync_studio_layer\\(\\s*(\\w+)([^)]*)\\)"));
    const QRegularExpression word(QStringLiteral("\\b([a-z]+)\\b"));
    for (auto m = call.globalMatch(readText(studio + QStringLiteral("/CMakeLists.txt"))); m.hasNext();) {
        const auto c = m.next();
        if (c.captured(1) == QLatin1String("name"))
            continue; // the function's own definition
        QSet<QString> &d = deps[c.captured(1)];
        QString listed = c.captured(2);
        listed = listed.left(listed.indexOf(QStringLiteral("LIBS")));
        for (auto w = word.globalMatch(listed); w.hasNext();)
            d.insert(w.next().captured(1));
    }
    return deps;
}

// A cycle through `module` in `deps`, as "a -> b -> a", or empty.
QString cycleFrom(const QMap<QString, QSet<QString>> &deps, const QString &module, QStringList path)
{
    if (path.contains(module))
        return (path.mid(path.indexOf(module)) << module).join(QStringLiteral(" -> "));
    path << module;
    for (const QString &next : deps.value(module))
        if (const QString cycle = cycleFrom(deps, next, path); !cycle.isEmpty())
            return cycle;
    return {};
}

// Studio folder -> the studio folders its files include: "x/Y.h" counts when studio/x/Y.h exists
// (core has folders of the same names, tasks/ among them).
QMap<QString, QSet<QString>> studioIncludes(const QString &studio)
{
    const QRegularExpression include(QStringLiteral("^\\s*#\\s*include\\s*\"((\\w+)/[\\w.]+)\""),
                                     QRegularExpression::MultilineOption);
    QMap<QString, QSet<QString>> deps;
    for (const QString &folder : QDir(studio).entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QSet<QString> &d = deps[folder];
        QDirIterator it(studio + QLatin1Char('/') + folder, {QStringLiteral("*.h"), QStringLiteral("*.cpp")}, QDir::Files);
        while (it.hasNext()) {
            for (auto m = include.globalMatch(readText(it.next())); m.hasNext();) {
                const auto match = m.next();
                if (match.captured(2) != folder && QFile::exists(studio + QLatin1Char('/') + match.captured(1)))
                    d.insert(match.captured(2));
            }
        }
    }
    return deps;
}

} // namespace

static const QRegularExpression &bannedInclude()
{
    static const QRegularExpression banned(QStringLiteral(
        R"(^\s*#\s*include\s*[<"](QtGui|QtWidgets|QtOpenGL|QtMultimedia)(/|>|")|)"
        R"(^\s*#\s*include\s*[<"](QWidget|QPainter|QImage|QPixmap|QApplication|QGuiApplication|QColor|QUndoStack|QUndoCommand)[>"])"),
        QRegularExpression::MultilineOption);
    return banned;
}

class TestLayout : public QObject
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

    void coreIncludesFollowTheDeclaredDependencies()
    {
        const QString core = QStringLiteral(LIPSYNC_SOURCE_DIR "/core");
        const QMap<QString, QSet<QString>> deps = declaredDependencies(core);
        QVERIFY2(deps.size() >= 10 && deps.contains(QStringLiteral("annotation")), "core modules not found");
        const QRegularExpression include(QStringLiteral("^\\s*#\\s*include\\s*\"(\\w+)/"),
                                         QRegularExpression::MultilineOption);
        QStringList offenders;
        for (auto module = deps.cbegin(); module != deps.cend(); ++module) {
            QDirIterator it(core + QLatin1Char('/') + module.key(), {QStringLiteral("*.h"), QStringLiteral("*.cpp")},
                            QDir::Files);
            while (it.hasNext()) {
                const QString path = it.next();
                for (auto m = include.globalMatch(readText(path)); m.hasNext();) {
                    const QString used = m.next().captured(1);
                    if (used != module.key() && deps.contains(used) && !module.value().contains(used))
                        offenders << QStringLiteral("%1 includes %2/ but lipsync_%3 does not depend on lipsync_%2")
                                         .arg(QDir(core).relativeFilePath(path), used, module.key());
                }
            }
        }
        QVERIFY2(offenders.isEmpty(), qPrintable(offenders.join(QLatin1Char('\n'))));
    }

    void coreModulesFormNoCycle()
    {
        const QMap<QString, QSet<QString>> deps = declaredDependencies(QStringLiteral(LIPSYNC_SOURCE_DIR "/core"));
        for (auto module = deps.cbegin(); module != deps.cend(); ++module) {
            const QString cycle = cycleFrom(deps, module.key(), {});
            QVERIFY2(cycle.isEmpty(), qPrintable(cycle));
        }
        // The check itself finds a cycle where there is one.
        const QMap<QString, QSet<QString>> looped{{QStringLiteral("io"), {QStringLiteral("project")}},
                                                  {QStringLiteral("project"), {QStringLiteral("io")}}};
        QCOMPARE(cycleFrom(looped, QStringLiteral("io"), {}), QStringLiteral("io -> project -> io"));
    }

    void studioFoldersFormNoCycle()
    {
        const QMap<QString, QSet<QString>> deps = studioIncludes(QStringLiteral(LIPSYNC_SOURCE_DIR "/studio"));
        QVERIFY2(deps.size() >= 10 && deps.value(QStringLiteral("app")).contains(QStringLiteral("context")),
                 "studio folders not found");
        for (auto folder = deps.cbegin(); folder != deps.cend(); ++folder) {
            const QString cycle = cycleFrom(deps, folder.key(), {});
            QVERIFY2(cycle.isEmpty(), qPrintable(cycle));
        }
        // Only the window's folder includes app/, and the shared layers include no panel.
        for (auto folder = deps.cbegin(); folder != deps.cend(); ++folder)
            QVERIFY2(folder.key() == QLatin1String("app") || !folder.value().contains(QStringLiteral("app")),
                     qPrintable(folder.key() + QStringLiteral(" includes app/")));
        QCOMPARE(deps.value(QStringLiteral("document")), QSet<QString>());
        QCOMPARE(deps.value(QStringLiteral("context")), QSet<QString>{QStringLiteral("document")});
    }

    // Each studio folder is a library of its own (studio/CMakeLists.txt) that links the layers it
    // names; the folders it includes are among them, so the build files say the layering.
    void studioIncludesFollowTheDeclaredLayers()
    {
        const QString studio = QStringLiteral(LIPSYNC_SOURCE_DIR "/studio");
        const QMap<QString, QSet<QString>> declared = declaredStudioLayers(studio);
        const QMap<QString, QSet<QString>> included = studioIncludes(studio);
        QVERIFY2(declared.size() >= 10 && declared.value(QStringLiteral("app")).contains(QStringLiteral("context")),
                 "lipsync_studio_layer calls not found");
        QStringList offenders;
        for (auto folder = included.cbegin(); folder != included.cend(); ++folder) {
            if (!declared.contains(folder.key())) {
                offenders << folder.key() + QStringLiteral("/ is no lipsync_studio_layer");
                continue;
            }
            for (const QString &used : folder.value())
                if (!declared.value(folder.key()).contains(used))
                    offenders << QStringLiteral("%1/ includes %2/ but its layer does not link it").arg(folder.key(), used);
        }
        QVERIFY2(offenders.isEmpty(), qPrintable(offenders.join(QLatin1Char('\n'))));
    }

    // One place reads the environment (util/Environment), one names the project's AAM
    // (Project::aam) and one the Debian paths of the data we read (util/SystemPaths): elsewhere in
    // core/, cli/ and studio/ they are banned (after QGIS's test_banned_keywords), so a new
    // variable, a second AAM lookup or a second copy of a path cannot drift.
    void bannedPatternsStayInTheirOnePlace()
    {
        struct Rule
        {
            QRegularExpression pattern;
            QString home;
        };
        const Rule rules[] = {
            {QRegularExpression(QStringLiteral(R"(\bgetenv\s*\(|\bqEnvironmentVariable\w*\s*\(|\bqgetenv\s*\()")),
             QStringLiteral("core/util/Environment.cpp")},
            {QRegularExpression(QStringLiteral(R"(\bmodel\s*\(\s*"aam"\s*\))")), QStringLiteral("core/project/Project.h")},
            {QRegularExpression(QStringLiteral(R"(/usr/(share|lib)/)")), QStringLiteral("core/util/SystemPaths.h")},
        };
        // The patterns match what they ban.
        QVERIFY(rules[0].pattern.match(QStringLiteral("const char *e = std::getenv(\"X\");")).hasMatch());
        QVERIFY(rules[0].pattern.match(QStringLiteral("qEnvironmentVariable(\"X\")")).hasMatch());
        QVERIFY(rules[1].pattern.match(QStringLiteral("project.model(\"aam\")")).hasMatch());
        const QString root = QStringLiteral(LIPSYNC_SOURCE_DIR);
        QStringList offenders;
        QSet<QString> homesSeen;
        for (const QString &top : {QStringLiteral("core"), QStringLiteral("cli"), QStringLiteral("studio")}) {
            QDirIterator it(root + QLatin1Char('/') + top, {QStringLiteral("*.h"), QStringLiteral("*.cpp")}, QDir::Files,
                            QDirIterator::Subdirectories);
            while (it.hasNext()) {
                const QString path = QDir(root).relativeFilePath(it.next());
                const QString text = readText(root + QLatin1Char('/') + path);
                for (const Rule &rule : rules) {
                    if (!rule.pattern.match(text).hasMatch())
                        continue;
                    if (path == rule.home)
                        homesSeen.insert(path);
                    else
                        offenders << path + QStringLiteral(": ") + rule.pattern.pattern() + QStringLiteral(" belongs in ")
                                         + rule.home;
                }
            }
        }
        QVERIFY2(offenders.isEmpty(), qPrintable(offenders.join(QLatin1Char('\n'))));
        QCOMPARE(homesSeen.size(), 3); // each rule's one place uses it
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

QTEST_GUILESS_MAIN(TestLayout)
#include "tst_layout.moc"
