#include "timeline/AlignTask.h"

#include "align/Lexicon.h"
#include "align/PronunciationDictionary.h"
#include "align/Realignment.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QStringList>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>

namespace lipsync::studio {

AlignOutcome alignSequence(const AlignJob &job, const Aligner &aligner, Feedback &feedback)
{
    AlignOutcome outcome;
    outcome.row = job.row;
    outcome.sequenceId = job.sequenceId;
    outcome.mediaPath = job.mediaPath;
    const std::string path = job.mediaPath.toStdString();
    const Lexicon lexicon(&PronunciationDictionary::cmu(), Lexicon::parseOverrides(job.pronunciations));
    auto noteGuesses = [&](const std::vector<std::string> &words) {
        for (const auto &[word, phones] : lexicon.guessed(words))
            outcome.guessed.emplace_back(word, PronunciationDictionary::toString(phones));
    };
    AlignmentResult r;
    std::optional<TranscriptFit> fit;
    if (job.stretches.empty()) {
        const std::vector<std::string> words = Lexicon::splitWords(job.transcript);
        if (words.empty())
            throw Error("the sequence has no transcript to align", path);
        noteGuesses(words);
        const AlignerOutput aligned = aligner.align(path, words, lexicon, feedback);
        r = aligned.alignment;
        fit = aligned.transcriptFit;
    } else {
        // Constrained re-alignment (core/align/Realignment): every boundary outside the
        // stretches kept exactly.
        const Realignment realignment(job.current.words, job.current.phones, job.stretches);
        noteGuesses(realignment.words());
        r = aligner.realign(path, realignment, lexicon, feedback).alignment;
        fit = job.current.transcriptFit; // the same words: the whole clip's fit stands
    }
    outcome.tiers = TierPair{r.words, r.phones, fit};
    outcome.tiers.words.name = "words";
    outcome.tiers.phones.name = "phones";
    outcome.ok = true;
    return outcome;
}

Task *startAlignment(TaskRunner &runner, const QString &title, std::vector<AlignJob> jobs,
                     std::shared_ptr<AlignerCache> aligners, std::function<void(std::vector<AlignOutcome>)> apply)
{
    return runner.start(title, [jobs = std::move(jobs), aligners, apply = std::move(apply)](Feedback &f) {
        // Every aligner the jobs choose, loaded first: a missing model fails the task at once.
        f.setStatus("loading the aligner model");
        std::map<AlignerChoice, std::shared_ptr<const Aligner>> loaded;
        for (const AlignJob &job : jobs)
            if (!loaded.count(job.aligner))
                loaded[job.aligner] = aligners->get(job.aligner);
        auto outcomes = std::make_shared<std::vector<AlignOutcome>>();
        QStringList failures;
        for (std::size_t i = 0; i < jobs.size(); ++i) {
            f.throwIfCanceled();
            f.setStatus(jobs[i].sequenceId.toStdString());
            f.setProgress(double(i) / double(jobs.size()));
            try {
                Feedback step(f, double(i) / double(jobs.size()), double(i + 1) / double(jobs.size()));
                outcomes->push_back(alignSequence(jobs[i], *loaded.at(jobs[i].aligner), step));
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
    job.current = TierPair{sequence.words, sequence.phones, sequence.transcriptFit};
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
