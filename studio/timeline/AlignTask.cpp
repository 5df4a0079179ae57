#include "timeline/AlignTask.h"

#include "align/ShippedAlignerModel.h"

#include "align/AlignerUtterance.h"
#include "align/ForcedAligner.h"
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

const Lexicon &lexicon()
{
    static const Lexicon instance(&PronunciationDictionary::cmu());
    return instance;
}

// Replaces the intervals of `tier` inside [a, b] by `replacement` shifted by a.
void splice(Tier &tier, double a, double b, const Tier &replacement)
{
    constexpr double eps = 1e-6;
    std::vector<Interval> out;
    for (const Interval &iv : tier.intervals)
        if (!(iv.start >= a - eps && iv.end <= b + eps))
            out.push_back(iv);
    for (Interval iv : replacement.intervals) {
        iv.start = std::min(b, iv.start + a);
        iv.end = std::min(b, iv.end + a);
        if (iv.end > iv.start)
            out.push_back(iv);
    }
    std::stable_sort(out.begin(), out.end(), [](const Interval &x, const Interval &y) { return x.start < y.start; });
    tier.intervals = std::move(out);
}

std::vector<std::string> wordsIn(const Tier &words, double a, double b)
{
    std::vector<std::string> out;
    for (const Interval &iv : words.intervals)
        if (iv.start >= a - 1e-6 && iv.end <= b + 1e-6 && !tieredit::isSilenceLabel(iv.label))
            for (const std::string &w : Lexicon::splitWords(iv.label))
                out.push_back(w);
    return out;
}

AlignOutcome alignOne(const AlignJob &job, const AcousticModel &model)
{
    AlignOutcome outcome;
    outcome.row = job.row;
    outcome.sequenceId = job.sequenceId;
    outcome.mediaPath = job.mediaPath;
    const std::string id = job.sequenceId.toStdString();
    const std::string path = job.mediaPath.toStdString();
    const ForcedAligner aligner(model);
    if (job.stretches.empty()) {
        const std::vector<std::string> words = Lexicon::splitWords(job.transcript);
        if (words.empty())
            throw Error("the sequence has no transcript to align", path);
        const PreparedUtterance u = prepareUtterance(id, path, words, model, lexicon());
        AlignmentResult r;
        try {
            r = aligner.align(u.features, u.words, u.pronunciations, u.duration);
        } catch (const Error &e) {
            throw Error(e.reason(), path);
        }
        outcome.tiers = TierPair{r.words, r.phones};
    } else {
        std::vector<std::vector<std::string>> stretchWords;
        std::vector<std::string> all;
        for (const auto &[a, b] : job.stretches) {
            stretchWords.push_back(wordsIn(job.current.words, a, b));
            all.insert(all.end(), stretchWords.back().begin(), stretchWords.back().end());
        }
        const PreparedUtterance u = prepareUtterance(id, path, all, model, lexicon());
        const double shift = model.featureOptions().shiftSeconds;
        const int frames = int(u.features.rows());
        outcome.tiers = job.current;
        std::size_t first = 0;
        for (std::size_t k = 0; k < job.stretches.size(); ++k) {
            const auto [a, b] = job.stretches[k];
            const std::size_t n = stretchWords[k].size();
            const std::vector<std::vector<Pronunciation>> pron(u.pronunciations.begin() + long(first),
                                                               u.pronunciations.begin() + long(first + n));
            first += n;
            if (n == 0)
                continue;
            const int fa = std::clamp(int(std::lround(a / shift)), 0, frames);
            const int fb = std::clamp(int(std::lround(b / shift)), fa, frames);
            AlignmentResult r;
            try {
                r = aligner.align(u.features.middleRows(fa, fb - fa), stretchWords[k], pron, b - a);
            } catch (const Error &e) {
                throw Error(e.reason(), path);
            }
            splice(outcome.tiers.words, a, b, r.words);
            splice(outcome.tiers.phones, a, b, r.phones);
        }
    }
    outcome.tiers.words.name = "words";
    outcome.tiers.phones.name = "phones";
    outcome.ok = true;
    return outcome;
}

} // namespace

QString alignerModelPath()
{
#ifdef LIPSYNC_SOURCE_DIR
    return QString::fromStdString(shippedAlignerModelPath(LIPSYNC_SOURCE_DIR));
#else
    return QString::fromStdString(shippedAlignerModelPath());
#endif
}

Task *startAlignment(TaskRunner &runner, const QString &title, std::vector<AlignJob> jobs,
                     std::function<void(std::vector<AlignOutcome>)> apply)
{
    const QString modelPath = alignerModelPath();
    return runner.start(title, [jobs = std::move(jobs), apply = std::move(apply), modelPath](Feedback &f) {
        if (modelPath.isEmpty())
            throw Error("the aligner model resources/aligner/grid-s1.aligner was not found "
                        "(set LIPSYNC_ALIGNER_MODEL to a model trained with `lipsync aligner train`)");
        f.setStatus("loading the aligner model");
        const std::shared_ptr<const AcousticModel> model = loadModel(modelPath);
        auto outcomes = std::make_shared<std::vector<AlignOutcome>>();
        QStringList failures;
        for (std::size_t i = 0; i < jobs.size(); ++i) {
            f.throwIfCanceled();
            f.setStatus(jobs[i].sequenceId.toStdString());
            f.setProgress(double(i) / double(jobs.size()));
            try {
                outcomes->push_back(alignOne(jobs[i], *model));
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

std::vector<std::pair<double, double>> realignStretches(const TierPair &tiers, double a, double b)
{
    std::vector<std::pair<double, double>> out;
    if (b < a)
        std::swap(a, b);
    bool open = false;
    bool spoken = false;
    double runStart = 0, runEnd = 0;
    auto close = [&] {
        if (open && spoken)
            out.emplace_back(runStart, runEnd);
        open = spoken = false;
    };
    for (const Interval &w : tiers.words.intervals) {
        if (w.end <= a + 1e-9 || w.start >= b - 1e-9) {
            close();
            continue;
        }
        bool fixed = w.userEdited;
        for (const Interval &p : tiers.phones.intervals)
            if (p.userEdited && p.end > w.start + 1e-6 && p.start < w.end - 1e-6)
                fixed = true;
        if (fixed) {
            close();
            continue;
        }
        if (!open) {
            open = true;
            runStart = w.start;
        }
        runEnd = w.end;
        spoken = spoken || !tieredit::isSilenceLabel(w.label);
    }
    close();
    return out;
}

} // namespace lipsync::studio
