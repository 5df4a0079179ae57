// Mouth cues (animation/MouthCues, MouthMapping) on the demo project's tracked, aligned clips:
//  - Rhubarb's semantics: X exactly in silence, A on every /p b m/ frame, cues contiguous from 0
//    to the end of the last frame;
//  - the mapping learned from the person's frames: wide-open D opens wider than B, puckered F is
//    narrower than C; features move some frames off their phone's shape, not most;
//  - a shape of the user's (Project::mouthShapes) takes the frames that look like it;
//  - every format written and read back; Rhubarb's exact layout; bad files named with the line.
#include "aam/AamModel.h"
#include "animation/MouthCues.h"
#include "animation/MouthMapping.h"
#include "animation/MouthTrack.h"
#include "io/AtomicFile.h"
#include "project/Project.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo";

MouthShape shapeAt(const MouthCueTrack &cues, double t)
{
    for (const MouthCue &c : cues.cues)
        if (t >= c.start && t < c.end)
            return c.shape;
    return MouthShape::X;
}

} // namespace

class TestMouthCues : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        m_project = Project::load(kDemo);
        m_aam = std::make_unique<AamModel>(AamModel::load(m_project.resolve(m_project.aam()->file)));
        m_measurer = std::make_unique<MouthMeasurer>(*m_aam);
        m_mapping = projectMouthMapping(*m_measurer, m_project, &m_tracks);
        QCOMPARE(m_tracks.size(), m_project.sequences.size());
    }

    // One sequence's cues: its track is the one the mapping learned from (measured once), the
    // same as measuring it alone.
    void aSequencesTrackIsTheLearnedOne()
    {
        const Sequence &s = m_project.sequences[2];
        const auto [mapping, track] = projectMouthMappingAndTrack(*m_measurer, m_project, s);
        QCOMPARE(track.sequenceId, s.id);
        QCOMPARE(mapping.shape(MouthShape::D), m_mapping.shape(MouthShape::D));
        const MouthTrack alone = mouthTrackOfSequence(*m_measurer, m_project, s);
        QCOMPARE(track.frameCount(), alone.frameCount());
        QVERIFY(track.points.isApprox(alone.points));
        QCOMPARE(track.phones, alone.phones);
    }

    void rhubarbSemantics()
    {
        int speechFrames = 0, offSeed = 0;
        for (const MouthTrack &track : m_tracks) {
            const MouthCueTrack cues = mouthCues(track, m_mapping);
            QVERIFY(!cues.cues.empty());
            QCOMPARE(cues.cues.front().start, 0.0);
            QCOMPARE(cues.duration, track.frames.endTime());
            QCOMPARE(cues.cues.back().end, cues.duration);
            for (size_t i = 1; i < cues.cues.size(); ++i) {
                QCOMPARE(cues.cues[i].start, cues.cues[i - 1].end);
                QVERIFY(cues.cues[i].shape != cues.cues[i - 1].shape);
            }
            for (int f = 0; f < track.frameCount(); ++f) {
                const int phone = track.phones[size_t(f)];
                const MouthShape shape = shapeAt(cues, track.frames.centre(f));
                const bool silent = phone == PhoneSet::kSilence || phone == PhoneSet::kBreath;
                QCOMPARE(shape == MouthShape::X, silent);
                if (PhoneSet::isBilabial(phone))
                    QCOMPARE(shape, MouthShape::A);
                if (!silent && !PhoneSet::isBilabial(phone)) {
                    ++speechFrames;
                    offSeed += shape != seedShapeOfPhone(phone) ? 1 : 0;
                }
            }
        }
        // The person's mouth decides some frames against the phone's shape; the phone most.
        QVERIFY2(offSeed > speechFrames / 20 && offSeed < speechFrames / 2,
                 qPrintable(QStringLiteral("%1 of %2").arg(offSeed).arg(speechFrames)));
    }

    void mappingLearnedFromTheFrames()
    {
        const auto opening = [this](MouthShape s) { return m_mapping.shape(s)[0]; };
        const auto width = [this](MouthShape s) { return m_mapping.shape(s)[1]; };
        // Taught by the frames of their phones (GRID s1 has no AO or ER: E keeps its drawing).
        for (MouthShape s : {MouthShape::A, MouthShape::B, MouthShape::C, MouthShape::D, MouthShape::F})
            QVERIFY(m_mapping.framesOf(s) >= 20);
        QCOMPARE(m_mapping.framesOf(MouthShape::E), 0);
        // Closures are the least open of the speech shapes; puckered lips the narrowest.
        for (MouthShape s : {MouthShape::B, MouthShape::C, MouthShape::D, MouthShape::F}) {
            QVERIFY2(opening(MouthShape::A) < opening(s), &"ABCDEFGHX"[int(s)]);
            if (s != MouthShape::F)
                QVERIFY2(width(MouthShape::F) < width(s), &"ABCDEFGHX"[int(s)]);
        }
        // Too little speech to learn from: refused, saying how much is needed.
        MouthTrack silent = m_tracks.front();
        std::fill(silent.phones.begin(), silent.phones.end(), PhoneSet::kSilence);
        try {
            MouthMapping::learn({silent});
            QFAIL("learned from silence");
        } catch (const Error &e) {
            QVERIFY2(QString::fromUtf8(e.what()).contains("at least 50"), e.what());
        }
    }

    void usersShapeTakesTheFramesLikeIt()
    {
        // A speech frame its phone's shape S holds; the user draws S elsewhere and another shape
        // T exactly like this frame: the frame goes to T.
        const MouthTrack &track = m_tracks.front();
        int frame = -1;
        for (int f = 0; f < track.frameCount() && frame < 0; ++f) {
            const int phone = track.phones[size_t(f)];
            const MouthShape seed = seedShapeOfPhone(phone);
            if (seed != MouthShape::A && seed != MouthShape::X && m_mapping.classify(track.measures[size_t(f)], phone) == seed)
                frame = f;
        }
        QVERIFY(frame >= 0);
        const int phone = track.phones[size_t(frame)];
        const MouthShape seed = seedShapeOfPhone(phone);
        const MouthShape other = seed == MouthShape::D ? MouthShape::C : MouthShape::D;
        const MouthMapping::CueFeatures f = m_mapping.cueFeatures(track.measures[size_t(frame)]);
        const std::array<double, 4> far{f[0] > 0.5 ? 0.0 : 1.0, f[1] > 0.5 ? 0.0 : 1.0, f[2] > 0.5 ? 0.0 : 1.0,
                                        f[3] > 0.5 ? 0.0 : 1.0};
        MouthMapping edited = m_mapping;
        edited.applyUserShapes({{std::string(1, mouthShapeLetter(seed)), far},
                                {std::string(1, mouthShapeLetter(other)), {f[0], f[1], f[2], f[3]}},
                                {"X", {1, 1, 1, 1}}});
        QVERIFY(edited.isUsers(seed) && edited.isUsers(other) && !edited.isUsers(MouthShape::X));
        QCOMPARE(edited.classify(track.measures[size_t(frame)], phone), other);
        QCOMPARE(m_mapping.classify(track.measures[size_t(frame)], phone), seed);
    }

    void everyFormatRoundTrips_data()
    {
        QTest::addColumn<QString>("suffix");
        for (const char *s : {"tsv", "json", "xml", "dat"})
            QTest::newRow(s) << QString::fromLatin1(s);
    }

    void everyFormatRoundTrips()
    {
        QFETCH(QString, suffix);
        const MouthCueTrack cues = mouthCues(m_tracks[1], m_mapping);
        QTemporaryDir dir;
        const std::string path = dir.filePath("cues." + suffix).toStdString();
        DatOptions dat;
        dat.frameRate = 25; // the demo's own: every cue starts on a frame
        writeMouthCues(cues, path, dat);
        const MouthCueTrack back = readMouthCues(path, dat);
        QCOMPARE(back.cues.size(), cues.cues.size());
        for (size_t i = 0; i < cues.cues.size(); ++i) {
            QCOMPARE(back.cues[i].shape, cues.cues[i].shape);
            QVERIFY(std::abs(back.cues[i].start - cues.cues[i].start) < 0.0051);
            QVERIFY2(std::abs(back.cues[i].end - cues.cues[i].end) < 0.0051,
                     qPrintable(QStringLiteral("%1: %2 vs %3").arg(i).arg(back.cues[i].end).arg(cues.cues[i].end)));
        }
        QVERIFY(std::abs(back.duration - cues.duration) < 0.0051);
        if (suffix == QLatin1String("json") || suffix == QLatin1String("xml"))
            QCOMPARE(back.soundFile, cues.soundFile);
    }

    void rhubarbLayout()
    {
        MouthCueTrack t;
        t.soundFile = "/sounds/a \"b\".wav";
        t.duration = 0.5;
        t.cues = {{0.0, 0.04, MouthShape::X}, {0.04, 0.2, MouthShape::D}, {0.2, 0.21, MouthShape::A},
                  {0.21, 0.5, MouthShape::G}};
        QCOMPARE(QString::fromStdString(formatMouthCues(t, CueFormat::Tsv)),
                 QStringLiteral("0.00\tX\n0.04\tD\n0.20\tA\n0.21\tG\n0.50\tX\n"));
        QCOMPARE(QString::fromStdString(formatMouthCues(t, CueFormat::Json)),
                 QStringLiteral("{\n  \"metadata\": {\n    \"soundFile\": \"/sounds/a \\\"b\\\".wav\",\n"
                                "    \"duration\": 0.50\n  },\n  \"mouthCues\": [\n"
                                "    { \"start\": 0.00, \"end\": 0.04, \"value\": \"X\" },\n"
                                "    { \"start\": 0.04, \"end\": 0.20, \"value\": \"D\" },\n"
                                "    { \"start\": 0.20, \"end\": 0.21, \"value\": \"A\" },\n"
                                "    { \"start\": 0.21, \"end\": 0.50, \"value\": \"G\" }\n  ]\n}\n"));
        const QString xml = QString::fromStdString(formatMouthCues(t, CueFormat::Xml));
        QVERIFY2(xml.contains("<rhubarbResult>\n  <metadata>\n    <soundFile>/sounds/a &quot;b&quot;.wav</soundFile>\n"
                              "    <duration>0.50</duration>\n  </metadata>\n  <mouthCues>\n"
                              "    <mouthCue start=\"0.00\" end=\"0.04\">X</mouthCue>"),
                 qPrintable(xml));
        // Moho at 24 fps: frame 1 + int(24 t); D at 0.04 falls on frame 1 with the X before it
        // and is dropped, as Rhubarb drops a cue that starts on the frame of the one before; the
        // end closes the mouth.
        QCOMPARE(QString::fromStdString(formatMouthCues(t, CueFormat::Dat)),
                 QStringLiteral("MohoSwitch1\n1 rest\n5 MBP\n6 FV\n13 rest\n"));
        DatOptions letters;
        letters.prestonBlair = false;
        QCOMPARE(QString::fromStdString(formatMouthCues(t, CueFormat::Dat, letters)),
                 QStringLiteral("MohoSwitch1\n1 X\n5 A\n6 G\n13 X\n"));
    }

    void badFilesAreNamed()
    {
        QTemporaryDir dir;
        const std::string tsv = dir.filePath("bad.tsv").toStdString();
        writeFileAtomically(tsv, "0.00\tX\n0.10\tQ\n0.20\tX\n");
        try {
            readMouthCues(tsv);
            QFAIL("read a bad shape");
        } catch (const Error &e) {
            QCOMPARE(e.file(), tsv);
            QCOMPARE(e.field(), std::string("line 2"));
        }
        const std::string dat = dir.filePath("bad.dat").toStdString();
        writeFileAtomically(dat, "Papagayo\n1 rest\n");
        QVERIFY_THROWS_EXCEPTION(Error, readMouthCues(dat));
        QVERIFY_THROWS_EXCEPTION(Error, writeMouthCues({}, dir.filePath("cues.txt").toStdString()));
        DatOptions slow;
        slow.frameRate = 12;
        QVERIFY_THROWS_EXCEPTION(Error, formatMouthCues({}, CueFormat::Dat, slow));
    }

private:
    Project m_project;
    std::unique_ptr<AamModel> m_aam;
    std::unique_ptr<MouthMeasurer> m_measurer;
    std::vector<MouthTrack> m_tracks;
    MouthMapping m_mapping;
};

QTEST_GUILESS_MAIN(TestMouthCues)
#include "tst_mouthcues.moc"
