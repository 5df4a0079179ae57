#pragma once
// The forced aligner of every command that aligns speech (`align`, `render`), chosen by one shared
// set of options (options()):
//   --aligner MODEL | sphinx[:DIR]  an aligner model of ours (default: the shipped GRID s1 model),
//                                   or CMU Sphinx's generic US-English model (SphinxAligner)
//   --adapt                         adapt the model to the recording's speaker first
//   --project DIR, --pronunciations DICT  pronunciations before the CMU dictionary and espeak-ng
#include "Command.h"

#include "align/AcousticModel.h"
#include "align/ForcedAligner.h"
#include "align/Lexicon.h"
#include "align/SpeakerAdaptation.h"
#include "align/SphinxAligner.h"
#include "audio/Mfcc.h"

#include <memory>
#include <optional>

namespace lipsync::cli {

class CommandLine;

class SpeechAligner
{
public:
    // The shared options, to add to a command's CommandSpec; `alignerAliases`: other spellings of
    // --aligner the command accepts.
    static std::vector<CommandOption> options(const QStringList &alignerAliases = {});

    struct Result
    {
        AlignmentResult alignment;
        double duration = 0;            // seconds of audio
        MfccOptions audioFrames;        // the aligner's audio frames (voteFrameLabels)
        AdaptationReport adaptation;    // ours with --adapt: log-likelihood per frame per pass
    };

    // Loads the aligner and the lexicon the options choose. Throws lipsync::Error naming the model
    // file or folder, the project or the dictionary at fault.
    explicit SpeechAligner(const CommandLine &args);
    ~SpeechAligner();

    // "sphinx:DIR" or the path of our model file.
    QString modelName() const { return m_modelName; }
    const Lexicon &lexicon() const { return *m_lexicon; }
    // Our model, null for Sphinx's.
    const AcousticModel *model() const { return m_model ? &*m_model : nullptr; }

    // Aligns the recording at `mediaPath` to `words`. Throws lipsync::Error naming the media (and
    // `transcriptPath` when the words do not fit the audio).
    Result align(const QString &mediaPath, const std::vector<std::string> &words,
                 const QString &transcriptPath) const;

private:
    QString m_modelName;
    bool m_adapt = false;
    std::optional<SphinxAligner> m_sphinx;
    std::optional<AcousticModel> m_model;
    std::unique_ptr<Lexicon> m_lexicon;
};

} // namespace lipsync::cli
