#pragma once
// The forced aligner of every command that aligns speech (`align`, `render`), chosen by one shared
// set of options (options()) into an AlignerChoice (align/Aligner.h):
//   --aligner MODEL | sphinx[:DIR]  an aligner model of ours, or CMU Sphinx's generic US-English
//                                   model (SphinxAligner); default: what --project says, else what
//                                   the dynamic model was trained with, else the shipped GRID s1 model
//   --adapt                         adapt the model to the recording's speaker first
//   --project DIR, --pronunciations DICT  pronunciations before the CMU dictionary and espeak-ng
#include "Command.h"

#include "align/Aligner.h"
#include "align/Lexicon.h"

#include <memory>
#include <optional>

namespace lipsync::cli {

class CommandLine;

class SpeechAligner
{
public:
    // The shared options, to add to a command's CommandSpec; `alignerAliases`: other spellings of
    // --aligner the command accepts. `withProject`: --project DIR among them.
    static std::vector<CommandOption> options(const QStringList &alignerAliases = {}, bool withProject = true);

    // Loads the aligner and the lexicon the options choose. Throws lipsync::Error naming the model
    // file or folder, the project or the dictionary at fault.
    // `transcriptFit`: measure AlignerOutput::transcriptFit (AlignerChoice::transcriptFit).
    explicit SpeechAligner(const CommandLine &args, bool transcriptFit = false);
    // The same with the pronunciations of the project at `projectFolder` (a command whose project
    // is an argument rather than --project). `recordingSeconds`: the length of what is aligned;
    // beyond what CMU Sphinx aligns, a Sphinx choice gives way to the shipped model
    // (fallBackForLongRecording; usesShippedForLong() says when it did).
    // `modelsAligner`: the aligner the dynamic model to generate with was trained with
    // (DynamicModel::trainingAligner), the default when neither --aligner nor the project says;
    // an own aligner model of the speaker's that is gone gives way to CMU Sphinx adapted (a note
    // on stderr says so).
    SpeechAligner(const CommandLine &args, const QString &projectFolder, bool transcriptFit = false,
                  double recordingSeconds = 0, const std::optional<AlignerChoice> &modelsAligner = std::nullopt);
    ~SpeechAligner();

    // "sphinx:DIR" or the path of our model file.
    QString modelName() const { return QString::fromStdString(m_aligner->name()); }
    // The file the model is read from (CMU Sphinx's: its folder's mdef), for up-to-date checks.
    QString modelFile() const;
    const Lexicon &lexicon() const { return *m_lexicon; }
    // CMU Sphinx was chosen, but the recording is too long for it.
    bool usesShippedForLong() const { return m_shippedForLong; }
    const Aligner &aligner() const { return *m_aligner; }

    // Aligns the recording at `mediaPath` to `words`. Throws lipsync::Error naming the media (and
    // `transcriptPath` when the words do not fit the audio).
    AlignerOutput align(const QString &mediaPath, const std::vector<std::string> &words,
                        const QString &transcriptPath, Feedback &feedback = Feedback::none()) const;
    // The same for a recording whose sound the caller holds (decoded once for every step).
    AlignerOutput align(const RecordingSound &sound, const std::vector<std::string> &words,
                        const QString &transcriptPath, Feedback &feedback = Feedback::none()) const;

    // align() for new speech in any voice (render, export animation; with transcriptFit), as
    // align/ProjectAligner's alignAnyVoice: the model --aligner did not name gives way to CMU
    // Sphinx's generic model adapted to the recording when the words misfit the voice and fit that
    // (a note on stderr says so). Words that fit neither are likely not the recording's: a warning
    // on stderr says so, and the alignment is returned all the same. `name` (optional) receives
    // the aligner used (Aligner::name).
    AlignerOutput alignAnyVoice(const RecordingSound &sound, const std::vector<std::string> &words,
                                const QString &transcriptPath, QString *name = nullptr) const;

private:
    std::unique_ptr<Aligner> m_aligner;
    std::unique_ptr<Lexicon> m_lexicon;
    bool m_shippedForLong = false;
    AlignerChoice m_choice;
    bool m_asked = false; // --aligner chose the model
};

} // namespace lipsync::cli
