#include "SpeechAligner.h"

#include "AlignerSupport.h"
#include "CommandLine.h"

#include "align/ProjectAligner.h"
#include "project/Project.h"

#include <QFileInfo>

#include <algorithm>
#include <cstdio>

namespace lipsync::cli {

std::vector<CommandOption> SpeechAligner::options(const QStringList &alignerAliases, bool withProject)
{
    std::vector<CommandOption> options{
        {QStringLiteral("aligner"), QStringLiteral("MODEL|sphinx[:DIR]"),
         QStringLiteral("the forced aligner: an aligner model of ours (lipsync aligner train/adapt/calibrate), or "
                        "sphinx: CMU Sphinx's generic US-English triphone model (many speakers; Debian package "
                        "pocketsphinx-en-us) at its Debian folder, or at DIR. Default: what --project says, else "
                        "the one the dynamic model to render was trained with (its file records it), else the "
                        "shipped GRID s1 model (one speaker) or $LIPSYNC_ALIGNER_MODEL"),
         {}, CommandOption::Optional, alignerAliases},
        {QStringLiteral("adapt"), {},
         QStringLiteral("adapt the aligner's model to the recording's speaker first (ours: MLLR + MAP of the "
                        "means, 3 passes; sphinx: one MLLR pass, about twice the time)")},
        {QStringLiteral("no-boundary-correction"), {},
         QStringLiteral("ours: leave the model's word-boundary correction (aligner calibrate) unapplied: the HMM's "
                        "own boundaries, as the paper's aligner")},
        {QStringLiteral("project"), QStringLiteral("DIR"),
         QStringLiteral("pronounce words with the project's pronunciations first, and align with the project's own "
                        "aligner model when it names one, or as the project says (generic: sphinx --adapt; "
                        "project create --aligner), unless --aligner")},
        pronunciationsOption(),
    };
    if (!withProject)
        options.erase(std::remove_if(options.begin(), options.end(),
                                     [](const CommandOption &o) { return o.name == QLatin1String("project"); }),
                      options.end());
    return options;
}

SpeechAligner::SpeechAligner(const CommandLine &args, bool transcriptFit)
    : SpeechAligner(args, args.value(QStringLiteral("project")), transcriptFit)
{
}

SpeechAligner::SpeechAligner(const CommandLine &args, const QString &projectFolder, bool transcriptFit,
                             double recordingSeconds, const std::optional<AlignerChoice> &modelsAligner)
{
    AlignerChoice choice{args.value(QStringLiteral("aligner")).toStdString(), args.isSet(QStringLiteral("adapt"))};
    m_asked = args.isSet(QStringLiteral("aligner"));
    choice.boundaryCorrection = !args.isSet(QStringLiteral("no-boundary-correction"));
    choice.transcriptFit = transcriptFit;
    bool said = !choice.model.empty(); // --aligner, then the project, then the model
    std::map<std::string, std::string> projectPronunciations;
    if (!projectFolder.isEmpty()) {
        const Project project = Project::load(projectFolder.toStdString());
        projectPronunciations = project.pronunciations;
        // The aligner the project says its speaker's speech is aligned with, unless --aligner names one.
        if (const std::optional<AlignerChoice> own = projectAlignerChoice(project); own && !said) {
            choice.model = own->model;
            choice.adapt = choice.adapt || own->adapt;
            said = true;
        }
    }
    // Else the aligner the model's training phones came from: the speaker's, not GRID s1's.
    if (modelsAligner && !said) {
        choice.model = modelsAligner->model;
        choice.adapt = choice.adapt || modelsAligner->adapt;
        if (!choice.model.empty() && !choice.isSphinx() && !QFileInfo::exists(QString::fromStdString(choice.model))) {
            std::fprintf(stderr,
                         "lipsync: note: the model was trained on phones of the aligner %s, which is not there: "
                         "aligning with CMU Sphinx's generic model adapted to the speaker\n",
                         choice.model.c_str());
            choice.useGenericAdapted();
        }
    }
    m_shippedForLong = fallBackForLongRecording(choice, recordingSeconds);
    if (!choice.isSphinx())
        choice.model = alignerModelOrDefault(QString::fromStdString(choice.model), args.spec().name).toStdString();
    m_choice = choice;
    m_aligner = createAligner(choice);
    m_lexicon = makeLexicon(args.value(QStringLiteral("pronunciations")), projectPronunciations);
}

SpeechAligner::~SpeechAligner() = default;

QString SpeechAligner::modelFile() const
{
    const QString name = modelName();
    return name.startsWith(QLatin1String("sphinx:")) ? name.mid(7) + QStringLiteral("/mdef") : name;
}

AlignerOutput SpeechAligner::align(const QString &mediaPath, const std::vector<std::string> &words,
                                   const QString &transcriptPath, Feedback &feedback) const
{
    return m_aligner->align(mediaPath.toStdString(), words, *m_lexicon, feedback, transcriptPath.toStdString());
}

AlignerOutput SpeechAligner::align(const RecordingSound &sound, const std::vector<std::string> &words,
                                   const QString &transcriptPath, Feedback &feedback) const
{
    return m_aligner->align(sound, words, *m_lexicon, feedback, transcriptPath.toStdString());
}

AlignerOutput SpeechAligner::alignAnyVoice(const RecordingSound &sound, const std::vector<std::string> &words,
                                           const QString &transcriptPath, QString *name) const
{
    VoiceAlignment aligned = lipsync::alignAnyVoice(*m_aligner, m_choice, m_asked, sound, words, *m_lexicon,
                                                    Feedback::none(), transcriptPath.toStdString());
    if (aligned.generic)
        std::fprintf(stderr,
                     "lipsync: note: %s: the words misfit the voice with %s (fit %.2f); CMU Sphinx's generic model "
                     "adapted to the recording fits them (%.2f): aligned with it\n",
                     qPrintable(transcriptPath), qPrintable(modelName()), aligned.chosenFit->value,
                     aligned.output.transcriptFit->value);
    else if (transcriptMisfit(aligned.output.transcriptFit))
        std::fprintf(stderr, "lipsync: warning: %s: %s: the mouth will not match the sound%s\n",
                     qPrintable(transcriptPath), aligned.output.transcriptFit->reason().c_str(),
                     aligned.genericTried() ? " (with CMU Sphinx's generic model adapted to the voice too)" : "");
    if (name)
        *name = QString::fromStdString(aligned.aligner);
    return std::move(aligned.output);
}

} // namespace lipsync::cli
