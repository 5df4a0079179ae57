#include "timeline/AlignTask.h"

#include "align/ShippedAlignerModel.h"

#include "align/AlignerUtterance.h"
#include "align/ForcedAligner.h"
#include "align/Realignment.h"
#include "align/SpeakerAdaptation.h"
#include "align/SphinxAligner.h"
#include "io/AudioDecoder.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

namespace lipsync::studio {

namespace {


// Loaded once per path and shared by every alignment (the model is read-only once prepared).
std::shared_ptr<const AcousticModel> loadModel(const QString &path)
{
    static std::mutex mutex;
    static std::map<QString, std::shared_ptr<const AcousticModel>> cache;
    const std::lock_guard lock(mutex);
    auto &slot = cache[path];
    if (!slot)
        slot = std::make_shared<const AcousticModel>(AcousticModel::load(path.toStdString()));
    return slot;
}

// One SphinxAligner per process and choice of speaker adaptation: its decoders (a few hundred ms
// to load) are reused.
std::shared_ptr<const SphinxAligner> sphinxAligner(bool adapt)
{
    static std::mutex mutex;
    static std::shared_ptr<const SphinxAligner> aligners[2];
    const std::lock_guard lock(mutex);
    std::shared_ptr<const SphinxAligner> &aligner = aligners[adapt ? 1 : 0];
    if (!aligner) {
        SphinxAligner::Options options;
        options.adaptationPasses = adapt ? 1 : 0;
        aligner = std::make_shared<const SphinxAligner>(options);
    }
    return aligner;
}

// `model`, or when the job asks for it `model` adapted to the recording (kept in `adapted`).
const AcousticModel &modelFor(const AlignJob &job, const AcousticModel &model, const PreparedUtterance &u,
                              std::optional<AcousticModel> &adapted, Feedback &feedback)
{
    if (!job.adaptToSpeaker)
        return model;
    try {
        adapted = SpeakerAdaptation::adapt(model, u.pronunciations, u.features, {}, &feedback);
    } catch (const Error &e) {
        throw Error(e.reason(), job.mediaPath.toStdString());
    }
    return *adapted;
}

// The same job with CMU Sphinx's generic model (SphinxAligner), adapted to the recording
// (SphinxAdaptation) when the job asks for it.
TierPair alignWithSphinx(const AlignJob &job, const std::vector<std::string> &words, const Lexicon &lexicon,
                         const Realignment *realignment, Feedback &feedback)
{
    const std::string path = job.mediaPath.toStdString();
    try {
        const auto pronunciations = lexicon.pronounceAll(words);
        const AudioBuffer audio = AudioDecoder::decode(path, SphinxAligner::kSampleRate);
        const std::shared_ptr<const SphinxAligner> aligner = sphinxAligner(job.adaptToSpeaker);
        const AlignmentResult r = realignment
                                      ? realignment->runPiecewise(*aligner, audio.samples, pronunciations, &feedback)
                                      : aligner->align(audio.samples, words, pronunciations, audio.duration(), &feedback);
        return TierPair{r.words, r.phones};
    } catch (const Error &e) {
        throw Error(e.reason(), e.file().empty() ? path : e.file());
    }
}

} // namespace

AlignOutcome alignSequence(const AlignJob &job, const AcousticModel *model, Feedback &feedback)
{
    AlignOutcome outcome;
    outcome.row = job.row;
    outcome.sequenceId = job.sequenceId;
    outcome.mediaPath = job.mediaPath;
    const std::string id = job.sequenceId.toStdString();
    const std::string path = job.mediaPath.toStdString();
    std::optional<AcousticModel> adapted;
    const Lexicon lexicon(&PronunciationDictionary::cmu(), Lexicon::parseOverrides(job.pronunciations));
    auto noteGuesses = [&](const std::vector<std::string> &words) {
        for (const auto &[word, phones] : lexicon.guessed(words))
            outcome.guessed.emplace_back(word, PronunciationDictionary::toString(phones));
    };
    if (job.aligner == AlignerChoice::Sphinx) {
        std::optional<Realignment> realignment;
        if (!job.stretches.empty())
            realignment.emplace(job.current.words, job.current.phones, job.stretches);
        const std::vector<std::string> words = realignment ? realignment->words() : Lexicon::splitWords(job.transcript);
        if (words.empty())
            throw Error("the sequence has no transcript to align", path);
        noteGuesses(words);
        outcome.tiers = alignWithSphinx(job, words, lexicon, realignment ? &*realignment : nullptr, feedback);
    } else if (job.stretches.empty()) {
        const std::vector<std::string> words = Lexicon::splitWords(job.transcript);
        if (words.empty())
            throw Error("the sequence has no transcript to align", path);
        noteGuesses(words);
        const PreparedUtterance u = prepareUtterance(id, path, words, *model, lexicon);
        const ForcedAligner aligner(modelFor(job, *model, u, adapted, feedback));
        AlignmentResult r;
        try {
            r = aligner.align(u.features, u.words, u.pronunciations, u.duration);
        } catch (const Error &e) {
            throw Error(e.reason(), path);
        }
        outcome.tiers = TierPair{r.words, r.phones};
    } else {
        // Constrained re-alignment (core/align/Realignment): the whole word tier again, with
        // every boundary outside the stretches kept exactly.
        const Realignment realignment(job.current.words, job.current.phones, job.stretches);
        noteGuesses(realignment.words());
        const PreparedUtterance u = prepareUtterance(id, path, realignment.words(), *model, lexicon);
        const ForcedAligner aligner(modelFor(job, *model, u, adapted, feedback));
        AlignmentResult r;
        try {
            r = realignment.run(aligner, u.features, u.pronunciations, u.duration);
        } catch (const Error &e) {
            throw Error(e.reason(), path);
        }
        outcome.tiers = TierPair{r.words, r.phones};
    }
    outcome.tiers.words.name = "words";
    outcome.tiers.phones.name = "phones";
    outcome.ok = true;
    return outcome;
}

QString alignerModelPath()
{
    return QString::fromStdString(shippedAlignerModelPath());
}

Task *startAlignment(TaskRunner &runner, const QString &title, std::vector<AlignJob> jobs,
                     std::function<void(std::vector<AlignOutcome>)> apply)
{
    const QString modelPath = alignerModelPath();
    return runner.start(title, [jobs = std::move(jobs), apply = std::move(apply), modelPath](Feedback &f) {
        const bool shipped = std::any_of(jobs.begin(), jobs.end(),
                                         [](const AlignJob &j) { return j.aligner == AlignerChoice::Shipped; });
        if (shipped && modelPath.isEmpty())
            throw Error("the aligner model resources/aligner/grid-s1.aligner was not found "
                        "(set LIPSYNC_ALIGNER_MODEL to a model trained with `lipsync aligner train`)");
        f.setStatus("loading the aligner model");
        const std::shared_ptr<const AcousticModel> model = shipped ? loadModel(modelPath) : nullptr;
        auto outcomes = std::make_shared<std::vector<AlignOutcome>>();
        QStringList failures;
        for (std::size_t i = 0; i < jobs.size(); ++i) {
            f.throwIfCanceled();
            f.setStatus(jobs[i].sequenceId.toStdString());
            f.setProgress(double(i) / double(jobs.size()));
            try {
                Feedback step(f, double(i) / double(jobs.size()), double(i + 1) / double(jobs.size()));
                outcomes->push_back(alignSequence(jobs[i], model.get(), step));
            } catch (const Error &e) {
                AlignOutcome failed;
                failed.row = jobs[i].row;
                failed.sequenceId = jobs[i].sequenceId;
                failed.mediaPath = jobs[i].mediaPath;
                failed.error = QString::fromStdString(e.reason());
                failed.errorFile = QString::fromStdString(e.file());
                failures << jobs[i].sequenceId + QStringLiteral(": ") + failed.error;
                outcomes->push_back(std::move(failed));
            }
        }
        f.setProgress(1.0);
        if (jobs.size() == 1 && !outcomes->front().ok)
            throw Error(outcomes->front().error.toStdString(), outcomes->front().errorFile.toStdString());
        if (!jobs.empty() && failures.size() == int(jobs.size()))
            throw Error(failures.join(QLatin1Char('\n')).toStdString());
        return TaskRunner::Commit([apply, outcomes] { apply(std::move(*outcomes)); });
    });
}

SequenceAlignment alignmentFor(int row, const Sequence &sequence, const QString &mediaPath,
                               const std::map<std::string, std::string> &pronunciations)
{
    SequenceAlignment out;
    AlignJob &job = out.job;
    job.row = row;
    job.sequenceId = QString::fromStdString(sequence.id);
    job.mediaPath = mediaPath;
    job.transcript = sequence.transcript;
    job.pronunciations = pronunciations;
    auto edited = [](const Tier &tier) {
        return std::any_of(tier.intervals.begin(), tier.intervals.end(), [](const Interval &iv) { return iv.userEdited; });
    };
    if (!edited(sequence.words) && !edited(sequence.phones))
        return out;
    // The tier's spoken words (breaths, "[br]", are not in a transcript) against the transcript's,
    // as the dictionary spells them.
    auto spelled = [](const std::vector<std::string> &words) {
        std::vector<std::string> out;
        for (const std::string &w : words)
            if (const std::string n = PronunciationDictionary::normalizeWord(w); !n.empty() && w.front() != '[')
                out.push_back(n);
        return out;
    };
    if (spelled(Realignment(sequence.words, sequence.phones, {}).words()) != spelled(Lexicon::splitWords(sequence.transcript))) {
        out.discardsEdits = true;
        return out;
    }
    job.current = TierPair{sequence.words, sequence.phones};
    job.stretches = Realignment::freeStretches(sequence.words, sequence.phones, 0.0,
                                               std::max(sequence.words.endTime(), sequence.phones.endTime()));
    out.nothingToAlign = job.stretches.empty();
    return out;
}

std::vector<std::pair<double, double>> realignStretches(const TierPair &tiers, double a, double b)
{
    return Realignment::freeStretches(tiers.words, tiers.phones, a, b);
}

} // namespace lipsync::studio
