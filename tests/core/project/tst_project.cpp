// The project document: manifest round trip, backups, atomic saves, validation of every field of
// a corrupt manifest, and import from a media folder (the bundled GRID demo clips).
#include "project/Project.h"
#include "project/ProjectManifest.h"
#include "util/Error.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#include <functional>

#include <cmath>
#include <limits>
#include <optional>

Q_DECLARE_METATYPE(std::vector<lipsync::Interval>)

using namespace lipsync;

namespace {

QString q(const std::string &s)
{
    return QString::fromStdString(s);
}

QByteArray readBytes(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll();
}

void writeBytes(const QString &path, const QByteArray &bytes)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(bytes);
}

// One sequence with landmarks in all four states (including an undefined point that kept its
// coordinates), both tiers with user-edited intervals, and awkward feature values; a second,
// bare one with an absolute media path.
Project makeProject()
{
    Project p;
    p.name = "round trip \"quoted\" ü";

    Sequence s;
    s.id = "s1";
    s.mediaFile = "media/s1.mpg";
    s.frameRate = 29.97;
    s.frameCount = 4;
    s.transcript = "set white";
    LandmarkSet set;
    for (int i = 0; i < LandmarkSet::kPointCount; ++i)
        set.points[size_t(i)] = {10.25 + i, 20.5 - i * 0.125, PointState(i % 4)};
    set.points[4] = {}; // never touched
    s.landmarks[0] = set;
    LandmarkSet fixedOnly;
    fixedOnly.points[22] = {1.0 / 3.0, -0.0, PointState::Fixed};
    s.landmarks[3] = fixedOnly;
    s.words.intervals = {{0.0, 0.5, "set", false}, {0.5, 0.9, "white", true}};
    s.phones.intervals = {{0.0, 0.1, "s", false}, {0.1, 0.3, "eh", true}, {0.35, 0.5, "t", false}};
    s.features.resize(4, 3);
    s.features << 1.0 / 3.0, -1e-12, 1e300, 0, 1, 2, -3.5, 4.25, 5e-7, 7, 8, 9;
    s.fitErrors = {0.0123456789012345, Sequence::kNoFace, 0.0, 2.5e-7};
    p.sequences.push_back(s);

    Sequence bare;
    bare.id = "s2";
    bare.mediaFile = "/somewhere/else/s2.wav";
    bare.frameRate = 25;
    bare.frameCount = 0;
    bare.transcript = "set blue at a one please";
    bare.transcriptProposed = true;
    bare.transcriptFit = TranscriptFit{-4.75, kSphinxTranscriptFitThreshold};
    bare.transcriptConfidence = {0.9, 0.25, 1.0, 0.5, 0.0625, 0.75};
    p.sequences.push_back(bare);

    p.models = {{"aam", "face model", "aam/face.aam"}, {"slds", "dynamics", "models/slds.json"}};
    p.aligner = Project::kGenericAligner;
    p.mouthShapes["D"] = {0.9, 0.625, 0.5, 0.25};
    p.pronunciations = {{"lipsync", "L IH1 P S IH2 NG K"}, {"o'neill", "OW N IY L"}};
    return p;
}

} // namespace

class TestProject : public QObject
{
    Q_OBJECT

private slots:
    void pointStateNames()
    {
        for (PointState s : {PointState::Undefined, PointState::Placed, PointState::Automatic,
                             PointState::Fixed}) {
            PointState back = PointState::Undefined;
            QVERIFY(pointStateFromName(pointStateName(s), back));
            QCOMPARE(back, s);
        }
        PointState state = PointState::Placed;
        QVERIFY(!pointStateFromName("moved", state));
        QCOMPARE(QString(pointStateName(PointState::Automatic)), QString("automatic"));
    }

    void landmarkCounts()
    {
        LandmarkSet set;
        QCOMPARE(set.definedCount(), 0);
        set.points[0].state = PointState::Placed;
        set.points[7].state = PointState::Fixed;
        QCOMPARE(set.definedCount(), 2);
        QVERIFY(!set.isComplete());
        for (auto &p : set.points)
            p.state = PointState::Automatic;
        QVERIFY(set.isComplete());
    }

    void tierIndexAt()
    {
        Tier tier{"words", {{0.0, 0.5, "a", false}, {0.5, 0.9, "b", false}, {1.0, 1.2, "c", false}}};
        QCOMPARE(tier.indexAt(-0.1), -1);
        QCOMPARE(tier.indexAt(0.0), 0);
        QCOMPARE(tier.indexAt(0.49), 0);
        QCOMPARE(tier.indexAt(0.5), 1);
        QCOMPARE(tier.indexAt(0.95), -1); // the gap
        QCOMPARE(tier.indexAt(1.1), 2);
        QCOMPARE(tier.indexAt(1.2), -1);
        QCOMPARE(tier.endTime(), 1.2);
    }

    // The tier's invariant (Tier::defect), shared by the loader and the studio's edits.
    void tierDefects_data()
    {
        QTest::addColumn<std::vector<Interval>>("intervals");
        QTest::addColumn<int>("index");
        QTest::addColumn<QString>("member");
        QTest::addColumn<QString>("message");
        const double nan = std::numeric_limits<double>::quiet_NaN();
        QTest::newRow("valid, with a gap") << std::vector<Interval>{{0, 0.5, "a"}, {0.6, 0.9, "b"}} << -1 << "" << "";
        QTest::newRow("empty interval") << std::vector<Interval>{{0, 0.5, "a"}, {0.5, 0.5, "b"}} << -1 << "" << "";
        QTest::newRow("overlap by an ulp")
            << std::vector<Interval>{{0, 0.9500000000000001, "sil"}, {0.95, 1.0, "B"}} << 1 << "start"
            << "overlaps the previous interval (which ends at 0.95)";
        QTest::newRow("negative start") << std::vector<Interval>{{-0.1, 0.5, "a"}} << 0 << "start" << "must not be negative";
        QTest::newRow("end before start") << std::vector<Interval>{{0, 0.5, "a"}, {0.7, 0.6, "b"}} << 1 << "end"
                                          << "is before start";
        QTest::newRow("NaN end") << std::vector<Interval>{{0, nan, "a"}} << 0 << "end" << "must be a finite number";
    }

    void tierDefects()
    {
        QFETCH(std::vector<Interval>, intervals);
        QFETCH(int, index);
        QFETCH(QString, member);
        QFETCH(QString, message);
        const std::optional<TierDefect> d = Tier{"phones", intervals}.defect();
        QCOMPARE(d.has_value(), index >= 0);
        if (!d)
            return;
        QCOMPARE(d->index, index);
        QCOMPARE(q(d->member), member);
        QCOMPARE(q(d->message), message);
    }

    void roundTrip()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const Project original = makeProject();
        // The fixture must exercise every state, or the round trip proves less than it claims.
        int stateSeen[4] = {};
        for (const auto &p : original.sequences[0].landmarks.at(0).points)
            ++stateSeen[int(p.state)];
        for (int n : stateSeen)
            QVERIFY(n > 0);

        original.save(dir.path().toStdString());
        QVERIFY(QFileInfo(dir.filePath("project.json")).isFile());
        QVERIFY(QFileInfo(dir.filePath("features/s1.csv")).isFile());
        QVERIFY(!QFileInfo(dir.filePath("features/s2.csv")).exists());
        QVERIFY(!QFileInfo(dir.filePath("project.json.bak")).exists());
        const QByteArray text = readBytes(dir.filePath("project.json"));
        QVERIFY(text.contains("\"format\": \"lipsync-project\""));
        QVERIFY(text.contains("\"version\": 6"));
        QVERIFY(text.contains("\"features\": \"features/s1.csv\""));

        const Project loaded = Project::load(dir.path().toStdString());
        QCOMPARE(q(loaded.folder()), QDir::cleanPath(QFileInfo(dir.path()).absoluteFilePath()));
        QCOMPARE(loaded.sequences.size(), size_t(2));
        QCOMPARE(loaded.sequences[0].landmarks, original.sequences[0].landmarks);
        QCOMPARE(loaded.sequences[0].words, original.sequences[0].words);
        QCOMPARE(loaded.sequences[0].phones, original.sequences[0].phones);
        QVERIFY(loaded.sequences[0].features == original.sequences[0].features);
        QCOMPARE(loaded.sequences[0].fitErrors, original.sequences[0].fitErrors);
        QVERIFY(loaded.sequences[1].fitErrors.empty());
        QVERIFY(loaded.sequences[1].transcriptProposed && !loaded.sequences[0].transcriptProposed);
        QCOMPARE(text.count("transcriptProposed"), 1); // written only when true
        QVERIFY(loaded.sequences[1].transcriptFit);
        QCOMPARE(loaded.sequences[1].transcriptFit->value, -4.75);
        QCOMPARE(loaded.sequences[1].transcriptFit->threshold, kSphinxTranscriptFitThreshold);
        QVERIFY(loaded.sequences[1].transcriptFit->misfit());
        QVERIFY(!loaded.sequences[0].transcriptFit);
        QCOMPARE(text.count("\"transcriptFit\""), 1); // written only when measured
        QCOMPARE(text.count("\"transcriptFitThreshold\""), 1);
        QCOMPARE(loaded.sequences[1].transcriptConfidence, original.sequences[1].transcriptConfidence);
        QCOMPARE(text.count("transcriptConfidence"), 1);
        QCOMPARE(loaded.models, original.models);
        QCOMPARE(loaded.pronunciations, original.pronunciations);
        QCOMPARE(loaded.aligner, std::string("generic"));
        QVERIFY(loaded.alignsGeneric());
        QVERIFY(text.contains("{\"word\": \"lipsync\", \"phones\": \"L IH1 P S IH2 NG K\"}"));
        QCOMPARE(loaded.mouthShapes, original.mouthShapes);
        QVERIFY(text.contains("\"mouthShapes\": {\n    \"D\": [0.9, 0.625, 0.5, 0.25]\n  }"));
        QVERIFY(loaded == original);

        // Equality must notice a change, or the comparison above proves nothing.
        const auto differs = [&](const std::function<void(Project &)> &change) {
            Project changed = loaded;
            change(changed);
            return !(changed == original);
        };
        QVERIFY(differs([](Project &p) { p.mouthShapes["D"][3] = 0.5; }));
        QVERIFY(differs([](Project &p) { p.sequences[0].landmarks[3].points[22].state = PointState::Placed; }));
        QVERIFY(differs([](Project &p) { p.sequences[1].transcriptProposed = false; }));
        QVERIFY(differs([](Project &p) { p.sequences[1].transcriptFit.reset(); }));
        QVERIFY(differs([](Project &p) { p.sequences[1].transcriptFit->threshold = kTranscriptFitThreshold; }));
        QVERIFY(differs([](Project &p) { p.sequences[1].transcriptConfidence[4] = 0.125; }));
        QVERIFY(differs([](Project &p) { p.aligner = Project::kBuiltinAligner; }));
        // A model of the project's own aligner wins over what the project says.
        Project own = loaded;
        own.models.push_back({"aligner", "speaker", "models/speaker.aligner"});
        QVERIFY(!own.alignsGeneric());
        QVERIFY(differs([](Project &p) { p.sequences[0].features(2, 1) += 1e-9; }));
        QVERIFY(differs([](Project &p) { p.sequences[0].phones.intervals[1].userEdited = false; }));
        QVERIFY(differs([](Project &p) { p.sequences[0].fitErrors[1] = 0.5; }));
        QVERIFY(differs([](Project &p) { p.pronunciations["lipsync"] = "L IH P S IH N K"; }));

        // Loading by the manifest's own path works too.
        QVERIFY(Project::load(dir.filePath("project.json").toStdString()) == original);
    }

    // The blind study is part of the project: study.json beside the manifest, referenced by it;
    // saveStudy() rewrites only that file (a participant's answers after every trial).
    void studyRoundTrip()
    {
        QTemporaryDir dir;
        Project p = makeProject();
        p.study = ForcedChoiceStudy({"real", "dpds", "hmm"}, {"s1", "s2"}, 5);
        p.study->addParticipant("P01");
        p.save(dir.path().toStdString());
        QVERIFY(readBytes(dir.filePath("project.json")).contains("\"study\": \"study.json\""));
        Project loaded = Project::load(dir.path().toStdString());
        QVERIFY(loaded.study);
        QVERIFY(loaded == p);

        const QByteArray manifest = readBytes(dir.filePath("project.json"));
        loaded.study->answer(0, 2, StudyChoice::Right, 1.5);
        loaded.study->addParticipant("P02");
        loaded.saveStudy();
        QCOMPARE(readBytes(dir.filePath("project.json")), manifest); // manifest untouched
        const Project again = Project::load(dir.path().toStdString());
        QCOMPARE(again.study->sessions().size(), size_t(2));
        QVERIFY(again.study->sessions()[0].trials[2].choice == StudyChoice::Right);
        QVERIFY(again == loaded);

        // Equality sees the study; a missing study file is a load error naming the field.
        Project without = again;
        without.study.reset();
        QVERIFY(!(without == again));
        QVERIFY(QFile::remove(dir.filePath("study.json")));
        try {
            Project::load(dir.path().toStdString());
            QFAIL("loaded a project whose study file is missing");
        } catch (const Error &e) {
            QCOMPARE(QString::fromStdString(e.field()), QString("study"));
        }
        QVERIFY_THROWS_EXCEPTION(Error, Project().saveStudy());
    }

    void savesAreStable()
    {
        // save(load(x)) writes the same bytes: no drift in number formatting or key order.
        QTemporaryDir dir;
        makeProject().save(dir.path().toStdString());
        const QByteArray first = readBytes(dir.filePath("project.json"));
        Project::load(dir.path().toStdString()).save();
        QCOMPARE(readBytes(dir.filePath("project.json")), first);
    }

    void unchangedFeaturesAreNotRewritten()
    {
        // A save compares each sequence's features with its file in memory: the unchanged file
        // is left as it was (its time in the past stays), the changed one is replaced.
        QTemporaryDir dir;
        Project p = makeProject();
        Sequence copy = p.sequences.front();
        copy.id = "s3";
        p.sequences.push_back(copy);
        p.save(dir.path().toStdString());
        const QString kept = dir.filePath("features/s1.csv"), changed = dir.filePath("features/s3.csv");
        const QDateTime past = QDateTime::currentDateTime().addSecs(-3600);
        for (const QString &path : {kept, changed}) {
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadWrite) && f.setFileTime(past, QFileDevice::FileModificationTime));
        }
        p.sequences.back().features(1, 2) = 0.1;
        p.save(dir.path().toStdString());
        QVERIFY(QFileInfo(kept).lastModified() < past.addSecs(1));
        QVERIFY(QFileInfo(changed).lastModified() > past.addSecs(1));
        QVERIFY(!QFileInfo(dir.filePath("features/.saving")).exists());
        const Project loaded = Project::load(dir.path().toStdString());
        QCOMPARE(loaded.sequences.back().features, p.sequences.back().features);
        QCOMPARE(loaded.sequences.front().features, p.sequences.front().features);
    }

    void backupKeptOnSecondSave()
    {
        QTemporaryDir dir;
        Project p = makeProject();
        p.save(dir.path().toStdString());
        const QByteArray first = readBytes(dir.filePath("project.json"));
        QVERIFY(!QFileInfo(dir.filePath("project.json.bak")).exists());

        p.name = "second";
        p.setFolder(dir.path().toStdString());
        p.save();
        QCOMPARE(readBytes(dir.filePath("project.json.bak")), first);
        const QByteArray second = readBytes(dir.filePath("project.json"));
        QVERIFY(second != first);
        QCOMPARE(Project::load(dir.path().toStdString()).name, std::string("second"));

        p.name = "third";
        p.save();
        QCOMPARE(readBytes(dir.filePath("project.json.bak")), second);
    }

    void corruptManifest_data()
    {
        QTest::addColumn<QString>("folder");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("reason");
        const auto row = [](const char *folder, const char *field, const char *reason) {
            QTest::newRow(folder) << QString(folder) << QString(field) << QString(reason);
        };
        row("not_json", "line 3, column 1", "not valid JSON");
        row("not_object", "(top level)", "must be a JSON object");
        row("missing_format", "format", "missing");
        row("wrong_format", "format", "is 'praat-textgrid', expected 'lipsync-project'");
        row("missing_version", "version", "missing");
        row("version_not_integer", "version", "must be an integer, found 1.5");
        row("future_version", "version", "version 7 is newer than this build");
        row("version_zero", "version", "must be at least 1");
        row("name_not_string", "name", "must be a string, found an array");
        row("unknown_field", "sequences[1].framerate", "unknown field");
        row("missing_sequences", "sequences", "missing");
        row("sequences_not_array", "sequences", "must be an array, found an object");
        row("sequence_not_object", "sequences[1]", "must be an object, found a string");
        row("missing_id", "sequences[2].id", "missing");
        row("empty_id", "sequences[0].id", "must not be empty");
        row("id_with_slash", "sequences[1].id", "must not contain '/'");
        row("duplicate_id", "sequences[2].id", "'a' is used by an earlier sequence");
        row("missing_media_file", "sequences[1].mediaFile", "missing");
        row("frame_rate_negative", "sequences[2].frameRate", "must be a positive number, found -25");
        row("frame_rate_zero", "sequences[2].frameRate", "must be a positive number, found 0");
        row("frame_rate_string", "sequences[0].frameRate", "must be a positive number, found a string");
        row("frame_count_negative", "sequences[1].frameCount", "must be an integer >= 0, found -1");
        row("frame_count_fractional", "sequences[1].frameCount", "must be an integer >= 0, found 74.5");
        row("transcript_not_string", "sequences[0].transcript", "must be a string, found 42");
        row("transcript_confidence_count", "sequences[0].transcriptConfidence", "3 values for 2 words of the transcript");
        row("transcript_confidence_range", "sequences[0].transcriptConfidence[1]", "must be a probability (0 to 1), found 1.5");
        row("aligner_unknown", "aligner", "must be \"builtin\" or \"generic\", found \"grid\"");
        row("mouth_shape_unknown", "mouthShapes.X", "must be a mouth shape A to H");
        row("mouth_shape_out_of_range", "mouthShapes.D", "must be numbers from 0 to 1, found 1.5");
        row("transcript_fit_not_number", "sequences[0].transcriptFit", "must be a number (nats per frame), found a string");
        row("transcript_fit_threshold_not_number", "sequences[0].transcriptFitThreshold",
            "must be a number (nats per frame), found null");
        row("transcript_fit_threshold_alone", "sequences[0].transcriptFitThreshold", "is given without a transcriptFit");
        row("unknown_tier", "sequences[0].tiers.syllables", "unknown field");
        row("interval_end_before_start", "sequences[0].tiers.words[1].end", "is before start");
        row("interval_overlap", "sequences[0].tiers.words[1].start", "overlaps the previous interval");
        row("interval_negative_start", "sequences[0].tiers.words[0].start", "must not be negative");
        row("interval_label_missing", "sequences[0].tiers.words[0].label", "missing");
        row("interval_user_edited_not_bool", "sequences[0].tiers.words[1].userEdited",
            "must be true or false, found a string");
        row("interval_start_not_number", "sequences[1].tiers.phones[0].start",
            "must be a finite number, found a string");
        row("landmarks_not_array", "sequences[0].landmarks", "must be an array, found an object");
        row("landmark_frame_out_of_range", "sequences[0].landmarks[0].frame",
            "3 is not below frameCount 3");
        row("landmark_duplicate_frame", "sequences[0].landmarks[1].frame", "1 appears twice");
        row("landmark_point_count", "sequences[0].landmarks[0].points", "has 22 points, expected 23");
        row("landmark_unknown_state", "sequences[0].landmarks[0].points[22][2]",
            "unknown state 'moved'");
        row("landmark_point_malformed", "sequences[0].landmarks[0].points[22]",
            "must be null or [x, y, state]");
        row("landmark_coordinate_not_number", "sequences[0].landmarks[0].points[22][0]",
            "must be a finite number, found a string");
        row("features_missing_file", "sequences[1].features", "sequence 'b': referenced features file");
        row("features_nan", "sequences[1].features", "sequence 'b': ");
        row("features_wrong_rows", "sequences[1].features", "has 2 rows, expected frameCount 3");
        row("features_not_string", "sequences[1].features", "must be a string, found 7");
        row("fit_errors_count", "sequences[1].fitErrors", "has 2 values, expected one per frame (3)");
        row("fit_errors_negative", "sequences[1].fitErrors[2]", "must not be negative");
        row("fit_errors_not_number", "sequences[1].fitErrors[1]", "must be a finite number, found a string");
        row("models_not_array", "models", "must be an array, found a string");
        row("model_missing_kind", "models[0].kind", "missing");
        row("model_empty_file", "models[1].file", "must not be empty");
        row("pronunciation_unknown_phone", "pronunciations[1].phones", "'DX' is not one of the 41 phones");
        row("pronunciation_upper_case", "pronunciations[1].word", "'Grid' must be one lower-case word");
        row("pronunciation_duplicate", "pronunciations[1].word", "'lipsync' has an earlier entry");
        row("pronunciation_empty_phones", "pronunciations[1].phones", "must hold at least one phone");
    }

    void corruptManifest()
    {
        QFETCH(QString, folder);
        QFETCH(QString, field);
        QFETCH(QString, reason);
        const QString dir = QStringLiteral(LIPSYNC_TEST_DATA "/project/") + folder;
        const QString manifest = QDir::cleanPath(dir + "/project.json");
        QVERIFY2(QFileInfo(manifest).isFile(), qPrintable(manifest));
        try {
            Project::load(dir.toStdString());
            QFAIL("loaded a corrupt manifest");
        } catch (const Error &e) {
            const QString message = QString::fromStdString(e.what());
            QCOMPARE(q(e.file()), manifest);
            QCOMPARE(q(e.field()), field);
            QVERIFY2(message.startsWith(manifest + ": " + field + ": "), qPrintable(message));
            QVERIFY2(message.contains(reason), qPrintable(message));
        }
    }

    // A fit written before aligners gave their thresholds (version 4) is our aligner's.
    void transcriptFitWithoutThresholdIsOurs()
    {
        QTemporaryDir dir;
        QFile fixture(QStringLiteral(LIPSYNC_TEST_DATA "/project/transcript_fit_not_number/project.json"));
        QVERIFY(fixture.open(QIODevice::ReadOnly));
        QByteArray text = fixture.readAll();
        text.replace("\"transcriptFit\": \"low\"", "\"transcriptFit\": -2.5");
        writeBytes(dir.filePath(QStringLiteral("project.json")), text);
        const Project loaded = Project::load(dir.path().toStdString());
        QVERIFY(loaded.sequences[0].transcriptFit);
        QCOMPARE(loaded.sequences[0].transcriptFit->value, -2.5);
        QCOMPARE(loaded.sequences[0].transcriptFit->threshold, kTranscriptFitThreshold);
        QVERIFY(loaded.sequences[0].transcriptFit->misfit());
    }

    void featureErrorsNameTheFile()
    {
        const QString dir = QStringLiteral(LIPSYNC_TEST_DATA "/project/");
        try {
            Project::load((dir + "features_nan").toStdString());
            QFAIL("loaded NaN features");
        } catch (const Error &e) {
            const QString message = QString::fromStdString(e.what());
            QVERIFY2(message.contains("features_nan/features/b.csv"), qPrintable(message));
            QVERIFY2(message.contains("line 3"), qPrintable(message));
            QVERIFY2(message.contains("not finite"), qPrintable(message));
        }
        try {
            Project::load((dir + "features_missing_file").toStdString());
            QFAIL("loaded a project whose features file is missing");
        } catch (const Error &e) {
            const QString message = QString::fromStdString(e.what());
            QVERIFY2(message.contains("features_missing_file/features/b.csv' does not exist"),
                     qPrintable(message));
        }
    }

    void missingFolderOrManifest()
    {
        QTemporaryDir dir;
        try {
            Project::load(dir.path().toStdString());
            QFAIL("loaded an empty folder");
        } catch (const Error &e) {
            QVERIFY(QString(e.what()).contains(dir.filePath("project.json")));
            QVERIFY(QString(e.what()).contains("not a project folder"));
        }
        QVERIFY_THROWS_EXCEPTION(Error, Project::load(dir.filePath("nope").toStdString()));
    }

    void missingMediaIsNotALoadError()
    {
        const QString dir = QStringLiteral(LIPSYNC_TEST_DATA "/project/valid_media_elsewhere");
        const Project p = Project::load(dir.toStdString());
        QCOMPARE(p.name, std::string("fixture"));
        QCOMPARE(p.sequences.size(), size_t(3));
        const Sequence &a = p.sequences[0];
        QCOMPARE(q(p.mediaPath(a)), QDir::cleanPath(QFileInfo(dir).absoluteFilePath() + "/media/a.mpg"));
        QVERIFY(!QFileInfo::exists(q(p.mediaPath(a))));
        QCOMPARE(q(p.mediaPath(p.sequences[1])), QString("/elsewhere/disk/b.mpg"));
        QCOMPARE(a.landmarks.size(), size_t(1));
        QCOMPARE(a.landmarks.at(1).definedCount(), 1);
        QCOMPARE(a.landmarks.at(1).points[22], (LandmarkPoint{1.5, 2.5, PointState::Placed}));
        QCOMPARE(a.words.intervals.size(), size_t(2));
        QVERIFY(a.words.intervals[1].userEdited);
        const Sequence *b = p.sequence("b");
        QVERIFY(b);
        QCOMPARE(b->frameRate, 29.97);
        QCOMPARE(b->features.rows(), Eigen::Index(3));
        QCOMPARE(b->features.cols(), Eigen::Index(2));
        QCOMPARE(b->features(1, 1), 4.5);
        QCOMPARE(b->features(2, 0), -1.0);
        QCOMPARE(p.models.size(), size_t(2));
        QCOMPARE(p.models[1].kind, std::string("dpds"));
        QVERIFY(p.sequence("zz") == nullptr);
    }

    void saveRejectsInvalidContent()
    {
        QTemporaryDir dir;
        const std::string folder = dir.filePath("p").toStdString();
        Project p = makeProject();
        p.sequences[0].features(1, 2) = std::numeric_limits<double>::quiet_NaN();
        try {
            p.save(folder);
            QFAIL("saved NaN features");
        } catch (const Error &e) {
            QCOMPARE(q(e.field()), QString("sequences[0].features"));
            QVERIFY2(QString(e.what()).contains("sequence 's1'"), e.what());
            QVERIFY2(QString(e.what()).contains("NaN"), e.what());
        }
        QVERIFY(!QFileInfo::exists(dir.filePath("p/project.json")));

        p = makeProject();
        p.sequences[1].frameRate = -1;
        try {
            p.save(folder);
            QFAIL("saved a negative frame rate");
        } catch (const Error &e) {
            QCOMPARE(q(e.field()), QString("sequences[1].frameRate"));
        }
        p = makeProject();
        p.sequences[1].id = "s1";
        QVERIFY_THROWS_EXCEPTION(Error, p.save(folder));
        p = makeProject();
        p.sequences[0].fitErrors.pop_back();
        try {
            p.save(folder);
            QFAIL("saved fit errors for fewer frames than the sequence has");
        } catch (const Error &e) {
            QCOMPARE(q(e.field()), QString("sequences[0].fitErrors"));
        }
        p = makeProject();
        p.sequences[0].features.conservativeResize(3, Eigen::NoChange);
        QVERIFY_THROWS_EXCEPTION(Error, p.save(folder));
        p = makeProject();
        p.sequences[0].landmarks[7] = LandmarkSet{}; // beyond frameCount 4
        QVERIFY_THROWS_EXCEPTION(Error, p.save(folder));
        QVERIFY(!QFileInfo::exists(dir.filePath("p/project.json")));
        QVERIFY_THROWS_EXCEPTION(Error, Project().save()); // no folder yet

        // validate() is the same check without the disk, naming the field as load would.
        p = makeProject();
        p.validate();
        p.sequences[0].phones.intervals = {{0, 0.9500000000000001, "sil"}, {0.95, 1.0, "B"}};
        try {
            p.validate();
            QFAIL("validated overlapping phones");
        } catch (const Error &e) {
            QCOMPARE(q(e.field()), QString("sequences[0].tiers.phones[1].start"));
        }
    }

    void saveAsRebasesRelativePaths()
    {
        QTemporaryDir dir;
        const QString oldFolder = dir.filePath("old");
        const QString newFolder = dir.filePath("new/deeper");
        Project p = makeProject();
        p.save(oldFolder.toStdString());
        p = Project::load(oldFolder.toStdString());
        const std::string mediaBefore = p.mediaPath(p.sequences[0]);
        const std::string modelBefore = p.resolve(p.models[0].file);

        p.saveAs(newFolder.toStdString());
        QCOMPARE(q(p.folder()), QDir::cleanPath(QFileInfo(newFolder).absoluteFilePath()));
        QCOMPARE(p.sequences[0].mediaFile, std::string("../../old/media/s1.mpg"));
        QCOMPARE(p.sequences[1].mediaFile, std::string("/somewhere/else/s2.wav"));
        QCOMPARE(p.models[0].file, std::string("../../old/aam/face.aam"));
        QCOMPARE(p.mediaPath(p.sequences[0]), mediaBefore);
        QCOMPARE(p.resolve(p.models[0].file), modelBefore);
        QVERIFY(QFileInfo(newFolder + "/features/s1.csv").isFile());
        QVERIFY(!QFileInfo::exists(newFolder + "/project.json.bak"));

        const Project reloaded = Project::load(newFolder.toStdString());
        QVERIFY(reloaded == p);
        QCOMPARE(reloaded.mediaPath(reloaded.sequences[0]), mediaBefore);
        // The old project is untouched.
        QCOMPARE(Project::load(oldFolder.toStdString()).sequences[0].mediaFile,
                 std::string("media/s1.mpg"));
        QVERIFY(!QFileInfo::exists(oldFolder + "/project.json.bak"));
    }

    void failedSaveKeepsOldManifest()
    {
        QTemporaryDir dir;
        Project p = makeProject();
        p.save(dir.path().toStdString());
        const QByteArray before = readBytes(dir.filePath("project.json"));

        // Feature files cannot be written when features/ is a regular file.
        QVERIFY(QDir(dir.filePath("features")).removeRecursively());
        writeBytes(dir.filePath("features"), "in the way");
        p.name = "changed";
        try {
            p.save(dir.path().toStdString());
            QFAIL("save succeeded although features/ is a file");
        } catch (const Error &e) {
            // (A changed feature file is first written beside the one in use: features/.saving/.)
            QVERIFY2(QString(e.what()).contains("features/") && QString(e.what()).contains("s1.csv"), e.what());
        }
        QCOMPARE(readBytes(dir.filePath("project.json")), before);
        QVERIFY(!QFileInfo::exists(dir.filePath("project.json.bak")));

        // The backup cannot be written when project.json.bak is a folder: the manifest stays.
        QVERIFY(QFile::remove(dir.filePath("features")));
        QVERIFY(QDir().mkpath(dir.filePath("project.json.bak/blocker")));
        QVERIFY_THROWS_EXCEPTION(Error, p.save(dir.path().toStdString()));
        QCOMPARE(readBytes(dir.filePath("project.json")), before);
        QCOMPARE(Project::load(dir.path().toStdString()).name, makeProject().name);
    }

    void saveUnderRegularFileFails()
    {
        // Tests run as root, so permissions cannot make a folder unwritable; a path below a
        // regular file can never be created.
        QTemporaryDir dir;
        const QString file = dir.filePath("plain.txt");
        writeBytes(file, "keep me");
        const QString target = file + "/project";
        try {
            makeProject().save(target.toStdString());
            QFAIL("saved below a regular file");
        } catch (const Error &e) {
            QVERIFY2(QString(e.what()).contains(target), e.what());
        }
        QCOMPARE(readBytes(file), QByteArray("keep me"));
    }

    void manifestLayout()
    {
        // A landmark frame is one line, and keys come in reading order.
        const QByteArray text =
            ProjectManifest::serialize(ProjectManifest::toJson(makeProject(), "/tmp/x"));
        QVERIFY(text.startsWith("{\n  \"format\": \"lipsync-project\",\n  \"version\": 6,\n"));
        const qsizetype points = text.indexOf("\"points\": [[");
        QVERIFY(points > 0);
        QVERIFY(text.indexOf('\n', points) > text.indexOf("]]", points));
        QVERIFY(text.indexOf("\"id\"") < text.indexOf("\"mediaFile\""));
        QVERIFY(text.indexOf("\"mediaFile\"") < text.indexOf("\"landmarks\""));
        QVERIFY(text.contains(
            "{\"kind\": \"aam\", \"name\": \"face model\", \"file\": \"aam/face.aam\"}"));
    }

    void fromMediaFolderDemo()
    {
        const QString demo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");
        const Project p = Project::fromMediaFolder((demo + "/media").toStdString(), demo.toStdString());
        QCOMPARE(p.name, std::string("demo"));
        QCOMPARE(p.sequences.size(), size_t(10));
        for (const Sequence &s : p.sequences) {
            QCOMPARE(s.frameRate, 25.0);
            QCOMPARE(s.frameCount, 75);
            QVERIFY2(!s.transcript.empty(), s.id.c_str());
            QVERIFY(s.words.intervals.size() >= 6);
            QCOMPARE(s.mediaFile, "media/" + s.id + ".mpg");
            QVERIFY(QFileInfo(q(p.mediaPath(s))).isFile());
        }
        const Sequence *s = p.sequence("bbaf2n");
        QVERIFY(s);
        QCOMPARE(s->transcript, std::string("bin blue at f two now"));
        QCOMPARE(s->words.intervals[1].label, std::string("bin"));
        QCOMPARE(s->words.intervals[1].start, 0.95);
        QCOMPARE(s->words.name, std::string("words"));

        // Imported projects save and load like any other.
        QTemporaryDir dir;
        Project copy = p;
        copy.saveAs(dir.path().toStdString());
        QVERIFY(Project::load(dir.path().toStdString()) == copy);
        QCOMPARE(Project::load(dir.path().toStdString()).mediaPath(copy.sequences[0]),
                 p.mediaPath(p.sequences[0]));
    }

    void fromMediaFolderPlainTranscript()
    {
        QTemporaryDir dir;
        const QString media = dir.filePath("media");
        QVERIFY(QDir().mkpath(media));
        QVERIFY(QFile::copy(QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg"),
                            media + "/take1.MPG"));
        writeBytes(media + "/take1.txt", "  place   green\n by d  two\n");
        writeBytes(media + "/notes.md", "not media");
        const Project p =
            Project::fromMediaFolder(media.toStdString(), dir.filePath("project").toStdString());
        QCOMPARE(p.sequences.size(), size_t(1));
        QCOMPARE(p.sequences[0].id, std::string("take1"));
        QCOMPARE(p.sequences[0].transcript, std::string("place green by d two"));
        QVERIFY(p.sequences[0].words.isEmpty());
        QCOMPARE(p.sequences[0].mediaFile, std::string("../media/take1.MPG"));
        QCOMPARE(p.sequences[0].frameCount, 75);
    }

    // Subtitles beside a clip give its transcript (their spoken words) when nothing else does.
    void fromMediaFolderSubtitles()
    {
        QTemporaryDir dir;
        const QString media = dir.filePath("media");
        QVERIFY(QDir().mkpath(media));
        for (const char *name : {"/a.mpg", "/b.mpg"})
            QVERIFY(QFile::copy(QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg"), media + name));
        writeBytes(media + "/a.srt", "1\n00:00:00,900 --> 00:00:02,100\n[Music] <i>bin blue</i>\nat f two now\n");
        writeBytes(media + "/b.vtt", "WEBVTT\n\n00:00.900 --> 00:02.100\n<v S1>bin blue at f</v>\n\n"
                                     "00:02.2 --> 00:02.9\n(sighs) two now\n");
        writeBytes(media + "/b.txt", "set white"); // a plain transcript wins over subtitles
        const Project p = Project::fromMediaFolder(media.toStdString(), dir.filePath("project").toStdString());
        QCOMPARE(p.sequences.size(), size_t(2));
        QCOMPARE(p.sequences[0].transcript, std::string("bin blue at f two now"));
        QCOMPARE(p.sequences[1].transcript, std::string("set white"));
        QFile::remove(media + "/b.txt");
        const Project q = Project::fromMediaFolder(media.toStdString(), dir.filePath("project").toStdString());
        QCOMPARE(q.sequences[1].transcript, std::string("bin blue at f two now"));
    }

    void fromMediaFolderAudioOnly()
    {
        // 1.2 s of 16 kHz mono silence: no video, so the nominal frame grid applies.
        QTemporaryDir dir;
        const qint32 rate = 16000, samples = 19200, bytes = samples * 2;
        QByteArray wav;
        QDataStream out(&wav, QIODevice::WriteOnly);
        out.setByteOrder(QDataStream::LittleEndian);
        out.writeRawData("RIFF", 4);
        out << qint32(36 + bytes);
        out.writeRawData("WAVEfmt ", 8);
        out << qint32(16) << qint16(1) << qint16(1) << rate << qint32(rate * 2) << qint16(2)
            << qint16(16);
        out.writeRawData("data", 4);
        out << qint32(bytes);
        wav.append(QByteArray(bytes, '\0'));
        writeBytes(dir.filePath("speech.wav"), wav);
        writeBytes(dir.filePath("speech.lab"), "lay red\n");
        const Project p = Project::fromMediaFolder(dir.path().toStdString(), dir.path().toStdString());
        QCOMPARE(p.sequences.size(), size_t(1));
        QCOMPARE(p.sequences[0].frameRate, Project::kAudioOnlyFrameRate);
        QCOMPARE(p.sequences[0].frameCount, 30);
        QCOMPARE(p.sequences[0].transcript, std::string("lay red"));
        QCOMPARE(p.sequences[0].mediaFile, std::string("speech.wav"));
    }

    void fromMediaFolderErrors()
    {
        QTemporaryDir dir;
        try {
            Project::fromMediaFolder(dir.path().toStdString(), dir.path().toStdString());
            QFAIL("imported an empty folder");
        } catch (const Error &e) {
            QVERIFY(QString(e.what()).contains(dir.path()));
            QVERIFY(QString(e.what()).contains("no media files"));
        }
        QVERIFY_THROWS_EXCEPTION(Error, Project::fromMediaFolder(dir.filePath("missing").toStdString(),
                                                                 dir.path().toStdString()));
        // A broken clip is reported by name rather than skipped.
        writeBytes(dir.filePath("broken.mpg"), "not an mpeg stream");
        try {
            Project::fromMediaFolder(dir.path().toStdString(), dir.path().toStdString());
            QFAIL("imported a broken clip");
        } catch (const Error &e) {
            QVERIFY2(QString(e.what()).contains("broken.mpg"), e.what());
        }
    }

    void bundledDemoProject()
    {
        const QString demo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");
        const Project p = Project::load(demo.toStdString());
        QCOMPARE(p.sequences.size(), size_t(10));
        QCOMPARE(p.aligner, std::string(Project::kBuiltinAligner)); // GRID's speaker: the shipped model
        for (const Sequence &s : p.sequences) {
            QVERIFY2(QFileInfo(q(p.mediaPath(s))).isFile(), s.mediaFile.c_str());
            QCOMPARE(s.frameCount, 75);
            QVERIFY(!s.transcript.empty());
        }
        // The bundled manifest is what the importer makes of the bundled clips, plus what
        // scripts/make-demo adds with the CLI: tracked features, aligned phones and the AAM.
        Project imported = Project::fromMediaFolder((demo + "/media").toStdString(), demo.toStdString());
        QCOMPARE(imported.sequences.size(), p.sequences.size());
        for (size_t i = 0; i < p.sequences.size(); ++i) {
            const Sequence &a = imported.sequences[i];
            const Sequence &b = p.sequences[i];
            QCOMPARE(b.id, a.id);
            QCOMPARE(b.mediaFile, a.mediaFile);
            QCOMPARE(b.frameRate, a.frameRate);
            QCOMPARE(b.frameCount, a.frameCount);
            QCOMPARE(b.transcript, a.transcript);
            QVERIFY(b.words == a.words);
            // Features: one row per frame, the same AAM parameters in every sequence, and
            // moving (a mouth that speaks), never constant.
            QCOMPARE(b.features.rows(), Eigen::Index(b.frameCount));
            QVERIFY(b.features.cols() > 0);
            QCOMPARE(b.features.cols(), p.sequences[0].features.cols());
            QVERIFY(b.features.allFinite());
            QVERIFY((b.features.colwise().maxCoeff() - b.features.colwise().minCoeff()).maxCoeff() > 0);
            // Phones: contiguous, inside the clip, starting and ending in silence, and every word
            // of the transcript covered by phones.
            QVERIFY(b.phones.intervals.size() > 6);
            QCOMPARE(b.phones.intervals.front().start, 0.0);
            QVERIFY(b.phones.intervals.back().end <= b.duration() + 0.05);
            for (size_t k = 1; k < b.phones.intervals.size(); ++k)
                QCOMPARE(b.phones.intervals[k].start, b.phones.intervals[k - 1].end);
            for (const Interval &w : b.words.intervals) {
                if (w.label == "sil")
                    continue;
                const int inside = b.phones.indexAt(0.5 * (w.start + w.end));
                QVERIFY2(inside >= 0 && b.phones.intervals[size_t(inside)].label != "sil", w.label.c_str());
            }
        }
        // The AAM the features were tracked with.
        QCOMPARE(p.models.size(), size_t(1));
        QCOMPARE(p.models[0].kind, std::string("aam"));
        QCOMPARE(p.models[0].file, std::string("aam/demo.aam"));
        QVERIFY(QFileInfo(q(p.resolve(p.models[0].file))).isFile());
    }
};

QTEST_GUILESS_MAIN(TestProject)
#include "tst_project.moc"
