#include "dynamics/PhoneCoverage.h"

#include "dynamics/ContextDependentModel.h"

#include <QJsonArray>

namespace lipsync {

PhoneCoverage PhoneCoverage::of(const std::vector<LabelledSequence> &sequences)
{
    PhoneCoverage c;
    double frameSeconds = 0;
    for (const LabelledSequence &s : sequences) {
        for (int label : s.labels)
            if (label >= 0 && label < PhoneSet::kCount) {
                ++c.frames[size_t(label)];
                if (PhoneSet::isSpeech(label))
                    frameSeconds += s.frameRate > 0 ? 1.0 / s.frameRate : 0.0;
            }
    }
    c.speechSeconds = frameSeconds;
    for (int n = 0; n < PhoneSet::kCount; ++n) {
        if (n == PhoneSet::kSilence || n == PhoneSet::kBreath)
            continue;
        if (c.frames[size_t(n)] == 0)
            c.unseen.push_back(PhoneSet::label(n));
        else if (c.frames[size_t(n)] < kMinimumVarianceFrames)
            c.rare.push_back(PhoneSet::label(n));
    }
    return c;
}

PhoneCoverage PhoneCoverage::of(const std::vector<LabelledSequence> &sequences, const DynamicModel &trained)
{
    PhoneCoverage c = of(sequences);
    if (const auto *context = dynamic_cast<const ContextDependentModel *>(&trained))
        c.contextStates = context->tree().stateCount();
    const std::optional<ModelKind> kind = parseModelKind(trained.kind());
    c.takesPrior = kind && modelKindTakesPrior(*kind);
    c.prior = trained.startedFromOtherSpeakers();
    return c;
}

namespace {
std::string joined(const std::vector<std::string> &phones)
{
    std::string out;
    for (const std::string &p : phones)
        out += (out.empty() ? "" : " ") + p;
    return out;
}
} // namespace

std::string PhoneCoverage::advice() const
{
    std::string out;
    if (!unseen.empty())
        out += std::to_string(unseen.size()) + " of " + std::to_string(kSpeechPhones)
               + " phones never occur in the training footage (" + joined(unseen) + "): "
               + (prior ? "their face comes from other speakers' mouths." : "the model guesses their face from the average.");
    if (!rare.empty())
        out += std::string(out.empty() ? "" : " ") + std::to_string(rare.size()) + " have fewer than "
               + std::to_string(kMinimumVarianceFrames) + " frames (" + joined(rare)
               + "): their spread is the average one.";
    if (contextStates > 0 && contextStates <= PhoneSet::kCount)
        out += std::string(out.empty() ? "" : " ") + "Phones in context made no context states ("
               + std::to_string(contextStates) + " states for " + std::to_string(PhoneSet::kCount)
               + " phones): too little footage for them.";
    if (!out.empty())
        out += " More footage of the person (" + std::to_string(int(speechSeconds + 0.5))
               + " s of speech now) covers more.";
    if (takesPrior && !prior && !priorTried && (!unseen.empty() || !rare.empty()))
        out += " Starting from other speakers' mouths (the prior) fills the phones this footage lacks.";
    return out;
}

QJsonObject PhoneCoverage::toJson() const
{
    QJsonArray u, r;
    for (const std::string &p : unseen)
        u.append(QString::fromStdString(p));
    for (const std::string &p : rare)
        r.append(QString::fromStdString(p));
    return QJsonObject{{"speechSeconds", speechSeconds},
                       {"unseen", u},
                       {"rare", r},
                       {"contextStates", contextStates},
                       {"prior", prior},
                       {"advice", QString::fromStdString(advice())}};
}

} // namespace lipsync
