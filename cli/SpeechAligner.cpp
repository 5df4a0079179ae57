#include "SpeechAligner.h"

#include "AlignerSupport.h"
#include "CommandLine.h"

#include "align/AlignerUtterance.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QFileInfo>

namespace lipsync::cli {

namespace {

// `sphinx` or `sphinx:DIR`: the model folder ("" = the default); nullopt for a model of ours.
std::optional<std::string> sphinxModelDir(const QString &aligner)
{
    if (aligner == QLatin1String("sphinx"))
        return std::string();
    if (aligner.startsWith(QLatin1String("sphinx:")))
        return aligner.mid(7).toStdString();
    return std::nullopt;
}

} // namespace

std::vector<CommandOption> SpeechAligner::options(const QStringList &alignerAliases)
{
    return {
        {QStringLiteral("aligner"), QStringLiteral("MODEL|sphinx[:DIR]"),
         QStringLiteral("the forced aligner: an aligner model of ours (lipsync aligner train/adapt; default: the "
                        "shipped GRID s1 model, one speaker, or $LIPSYNC_ALIGNER_MODEL), or sphinx: CMU Sphinx's "
                        "generic US-English triphone model (many speakers; Debian package pocketsphinx-en-us) at "
                        "its Debian folder, or at DIR"),
         {}, CommandOption::Optional, alignerAliases},
        {QStringLiteral("adapt"), {},
         QStringLiteral("adapt the aligner's model to the recording's speaker first (ours: MLLR + MAP of the "
                        "means, 3 passes; sphinx: one MLLR pass, about twice the time)")},
        {QStringLiteral("project"), QStringLiteral("DIR"),
         QStringLiteral("pronounce words with the project's pronunciations first")},
        pronunciationsOption(),
    };
}

SpeechAligner::SpeechAligner(const CommandLine &args) : m_adapt(args.isSet(QStringLiteral("adapt")))
{
    const QString aligner = args.value(QStringLiteral("aligner"));
    if (const std::optional<std::string> dir = sphinxModelDir(aligner)) {
        m_sphinx.emplace(SphinxAligner::Options{*dir, {}, m_adapt ? 1 : 0});
        m_modelName = QStringLiteral("sphinx:") + QString::fromStdString(m_sphinx->modelDir());
    } else {
        m_modelName = alignerModelOrDefault(aligner, args.spec().name);
        m_model = AcousticModel::load(m_modelName.toStdString());
    }
    std::map<std::string, std::string> projectPronunciations;
    if (!args.value(QStringLiteral("project")).isEmpty())
        projectPronunciations = Project::load(args.value(QStringLiteral("project")).toStdString()).pronunciations;
    m_lexicon = makeLexicon(args.value(QStringLiteral("pronunciations")), projectPronunciations);
}

SpeechAligner::~SpeechAligner() = default;

SpeechAligner::Result SpeechAligner::align(const QString &mediaPath, const std::vector<std::string> &words,
                                           const QString &transcriptPath) const
{
    Result result;
    if (m_sphinx) {
        // The CMU Sphinx model computes its own features from 16 kHz audio (decoded once); its
        // errors name the media file, and its tiers end with the audio.
        result.alignment = m_sphinx->align(mediaPath.toStdString(), words, *m_lexicon);
        result.duration = result.alignment.phones.intervals.back().end;
        return result;
    }
    const PreparedUtterance u = prepareUtterance(QFileInfo(mediaPath).completeBaseName().toStdString(),
                                                 mediaPath.toStdString(), words, *m_model, *m_lexicon);
    result.duration = u.duration;
    result.audioFrames = m_model->featureOptions();
    try {
        std::optional<AcousticModel> adapted;
        if (m_adapt)
            adapted = SpeakerAdaptation::adapt(*m_model, u.pronunciations, u.features, {}, nullptr, &result.adaptation);
        result.alignment =
            ForcedAligner(adapted ? *adapted : *m_model).align(u.features, u.words, u.pronunciations, u.duration);
    } catch (const Error &e) {
        throw Error(e.reason() + " (transcript " + transcriptPath.toStdString() + ")", mediaPath.toStdString());
    }
    return result;
}

} // namespace lipsync::cli
