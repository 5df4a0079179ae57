// Replays every input that once crashed a parser under libFuzzer
// (tests/data/fuzz/regressions/<parser>-<defect>.bin) and every seed of the fuzz corpora
// (tests/data/fuzz/<parser>/*): each must give a result or a lipsync::Error naming the file —
// never a crash, a sanitizer report or another exception.
#include "FuzzParsers.h"

#include "util/Error.h"

#include <QDir>
#include <QFile>
#include <QTest>

using namespace lipsync;

namespace {

const QString kFuzzData = QStringLiteral(LIPSYNC_TEST_DATA "/fuzz/");

QByteArray contents(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    return file.readAll();
}

} // namespace

class TestFuzzRegressions : public QObject
{
    Q_OBJECT
private slots:
    void everyParserHasSeeds()
    {
        for (const auto &[name, parse] : fuzz::parsers()) {
            const QDir seeds(kFuzzData + QString::fromStdString(name));
            QVERIFY2(!seeds.entryList(QDir::Files).isEmpty(), name.c_str());
        }
    }

    void regressions_data()
    {
        QTest::addColumn<QString>("parser");
        QTest::addColumn<QString>("file");
        const QDir dir(kFuzzData + QStringLiteral("regressions"));
        for (const QString &file : dir.entryList({QStringLiteral("*.bin")}, QDir::Files))
            QTest::newRow(qPrintable(file)) << file.section('-', 0, 0) << dir.filePath(file);
    }

    void regressions()
    {
        // The defect each file once triggered must now be a clean Error: these inputs are all bad.
        QFETCH(QString, parser);
        QFETCH(QString, file);
        const auto it = fuzz::parsers().find(parser.toStdString());
        QVERIFY2(it != fuzz::parsers().end(), qPrintable("no parser named " + parser));
        try {
            it->second(contents(file).toStdString());
            QFAIL("bad input was accepted");
        } catch (const Error &e) {
            QVERIFY(!e.reason().empty());
        }
    }

    void seeds_data()
    {
        QTest::addColumn<QString>("parser");
        QTest::addColumn<QString>("file");
        for (const auto &[name, parse] : fuzz::parsers()) {
            const QDir dir(kFuzzData + QString::fromStdString(name));
            for (const QString &file : dir.entryList(QDir::Files))
                QTest::newRow(qPrintable(QString::fromStdString(name) + "/" + file))
                    << QString::fromStdString(name) << dir.filePath(file);
        }
    }

    void seeds()
    {
        // Seeds are real files, most of them valid; a few are the bad-input examples of the unit
        // tests. Either way: a result or a clean Error.
        QFETCH(QString, parser);
        QFETCH(QString, file);
        try {
            fuzz::parsers().at(parser.toStdString())(contents(file).toStdString());
        } catch (const Error &) {
        }
    }
};

QTEST_GUILESS_MAIN(TestFuzzRegressions)
#include "tst_fuzzregressions.moc"
