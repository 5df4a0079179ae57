#include "document/ProjectDocument.h"

#include "document/AddSequencesCommand.h"
#include "document/LandmarkCommands.h"
#include "document/MouthShapesCommand.h"
#include "document/PronunciationCommand.h"
#include "document/SetTranscriptCommand.h"
#include "document/StudyCommands.h"
#include "document/TierCommands.h"
#include "project/ProjectManifest.h"
#include "util/Error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QUndoStack>
#include <QtDebug>

#include <algorithm>
#include <set>

namespace lipsync::studio {

ProjectDocument::ProjectDocument(QUndoStack *undoStack, QObject *parent)
    : QObject(parent), m_undo(undoStack)
{
}

void ProjectDocument::markUnsaved()
{
    m_undo->resetClean();
}

QString ProjectDocument::exportFolder() const
{
    if (m_open && !m_readOnly && !m_folder.isEmpty())
        return m_folder;
    return QDir::home().filePath(QStringLiteral("lipsync-projects"));
}

bool ProjectDocument::isModified() const
{
    return m_open && (!m_undo->isClean() || m_unsavedStudyData);
}

void ProjectDocument::reset(Project project, const QString &folder, bool readOnly)
{
    m_project = std::move(project);
    m_folder = folder;
    m_project.setFolder(folder.toStdString());
    m_readOnly = readOnly;
    m_open = true;
    m_unsavedStudyData = false;
    m_undo->clear();
    m_undo->setClean();
    emit documentReset();
    emit locationChanged();
}

QString ProjectDocument::mediaPath(int row) const
{
    return QString::fromStdString(m_project.resolve(sequence(row).mediaFile));
}

namespace {

// What a save created, removed again if the save fails: files copied into the target and the
// folders made for them (the target itself included when it did not exist), so a failed save
// leaves no half-written project behind.
class SaveRollback
{
public:
    explicit SaveRollback(const QString &folder) { makePath(folder); }
    ~SaveRollback()
    {
        if (m_committed)
            return;
        for (auto it = m_files.rbegin(); it != m_files.rend(); ++it)
            QFile::remove(*it);
        for (auto it = m_folders.rbegin(); it != m_folders.rend(); ++it)
            QDir(*it).removeRecursively();
    }
    // mkpath that remembers the outermost folder it created.
    void makePath(const QString &path)
    {
        QString missing;
        for (QString p = QDir::cleanPath(QFileInfo(path).absoluteFilePath()); !QFileInfo::exists(p);) {
            missing = p;
            const QString parent = QFileInfo(p).absolutePath();
            if (parent == p)
                break;
            p = parent;
        }
        if (!QDir().mkpath(path))
            throw Error("cannot create the folder", path.toStdString());
        if (!missing.isEmpty())
            m_folders << missing;
    }
    void copy(const QString &from, const QString &to, const char *what)
    {
        makePath(QFileInfo(to).absolutePath());
        if (!QFile::copy(from, to))
            throw Error(std::string("cannot copy the ") + what + " into the project", to.toStdString());
        m_files << to;
    }
    // A file the save may create: removed on failure if it is not there yet.
    void expect(const QString &file)
    {
        if (!QFileInfo::exists(file))
            m_files << file;
    }
    void commit() { m_committed = true; }

private:
    QStringList m_files, m_folders;
    bool m_committed = false;
};

} // namespace

void ProjectDocument::saveTo(const QString &folder)
{
    // Nothing is written for a project that would not load again.
    m_project.validate();
    const bool moving = QFileInfo(folder).absoluteFilePath() != QFileInfo(m_folder).absoluteFilePath();
    SaveRollback rollback(folder);
    // What Project::save itself writes besides the manifest (it keeps the manifest on disk
    // consistent at every moment, but not a new folder's other files).
    const QDir target(folder);
    rollback.expect(target.filePath(QString::fromLatin1(Project::kManifestName)));
    rollback.expect(target.filePath(QString::fromLatin1(Project::kStudyFileName)));
    if (std::any_of(m_project.sequences.begin(), m_project.sequences.end(),
                    [](const Sequence &s) { return s.features.size() > 0; })) {
        rollback.makePath(target.filePath(QStringLiteral("features")));
        for (const Sequence &s : m_project.sequences)
            if (s.features.size() > 0)
                rollback.expect(target.filePath(QString::fromStdString(ProjectManifest::featureFileName(s.id))));
    }
    if (m_readOnly && moving) {
        // The bundled demo may move or vanish with the installation: its copy takes the
        // (small) clips along, so it stays complete on its own.
        auto takeAlong = [&](const std::string &file, const char *what) {
            const QString relative = QString::fromStdString(file);
            const QString from = QString::fromStdString(m_project.resolve(file));
            const QString to = target.filePath(relative);
            if (!QFileInfo(relative).isAbsolute() && QFileInfo::exists(from) && !QFileInfo::exists(to))
                rollback.copy(from, to, what);
        };
        for (const Sequence &s : m_project.sequences)
            takeAlong(s.mediaFile, "media file");
        // So do the model files it refers to (the demo's AAM); models trained in memory are
        // written by their owners on locationChanged.
        for (const ModelReference &m : m_project.models)
            takeAlong(m.file, "model file");
        // Relative paths now hold in the new folder as they are: save from there.
        Project copy = m_project;
        copy.setFolder(folder.toStdString());
        copy.saveAs(folder.toStdString());
        m_project = std::move(copy);
    } else {
        // A user's project keeps referring to its media where they are (paths rebased).
        m_project.saveAs(folder.toStdString());
    }
    rollback.commit();
    m_folder = QString::fromStdString(m_project.folder());
    m_readOnly = false;
    m_unsavedStudyData = false;
    m_undo->setClean();
    emit locationChanged();
}

bool ProjectDocument::requestAddSequences(std::vector<Sequence> sequences, const QString &text)
{
    if (!m_open || sequences.empty())
        return false;
    // Every command leaves a document that saves and loads again: the new sequences get the
    // loader's checks (Project::validate), their ids must be new.
    std::set<std::string> ids;
    for (const Sequence &s : m_project.sequences)
        ids.insert(s.id);
    for (const Sequence &s : sequences)
        if (!ids.insert(s.id).second) {
            refuse(text, tr("the project already has a sequence %1").arg(QString::fromStdString(s.id)));
            return false;
        }
    Project added;
    added.setFolder(m_project.folder());
    added.sequences = sequences;
    try {
        added.validate();
    } catch (const Error &e) {
        refuse(text, QString::fromUtf8(e.what()));
        return false;
    }
    m_undo->push(new AddSequencesCommand(this, std::move(sequences), text));
    return true;
}

void ProjectDocument::applyAddSequences(std::vector<Sequence> sequences)
{
    const int first = sequenceCount();
    const int count = int(sequences.size());
    emit sequencesAboutToBeAdded(first, count);
    for (Sequence &s : sequences)
        m_project.sequences.push_back(std::move(s));
    emit sequencesAdded(first, count);
}

std::vector<Sequence> ProjectDocument::applyRemoveLastSequences(int count)
{
    const int first = sequenceCount() - count;
    emit sequencesAboutToBeRemoved(first, count);
    const auto from = m_project.sequences.begin() + first;
    std::vector<Sequence> removed(std::make_move_iterator(from), std::make_move_iterator(m_project.sequences.end()));
    m_project.sequences.erase(from, m_project.sequences.end());
    emit sequencesRemoved(first, count);
    return removed;
}

bool ProjectDocument::requestTranscriptChange(int row, const QString &transcript)
{
    if (row < 0 || row >= sequenceCount())
        return false;
    const Sequence &s = sequence(row);
    const TranscriptState before{QString::fromStdString(s.transcript), s.transcriptProposed, s.transcriptConfidence};
    const TranscriptState after{transcript.simplified(), false, {}};
    // The same words are no edit: a proposal stays proposed until edited or accepted.
    if (after.text == before.text)
        return false;
    m_undo->push(new SetTranscriptCommand(this, row, before, after, SetTranscriptCommand::Kind::Edit));
    return true;
}

bool ProjectDocument::requestProposedTranscript(int row, const QString &transcript, std::vector<double> confidence)
{
    if (row < 0 || row >= sequenceCount())
        return false;
    const Sequence &s = sequence(row);
    const TranscriptState before{QString::fromStdString(s.transcript), s.transcriptProposed, s.transcriptConfidence};
    // One posterior per word, each a probability, or none (what the manifest accepts).
    const bool usable = confidence.size() == Sequence::transcriptWords(transcript.toStdString()).size()
                        && std::all_of(confidence.begin(), confidence.end(), [](double c) { return c >= 0 && c <= 1; });
    const TranscriptState after{transcript.simplified(), true, usable ? std::move(confidence) : std::vector<double>()};
    if (after.text.isEmpty() || after == before)
        return false;
    m_undo->push(new SetTranscriptCommand(this, row, before, after, SetTranscriptCommand::Kind::Propose));
    return true;
}

bool ProjectDocument::requestAcceptTranscript(int row)
{
    if (row < 0 || row >= sequenceCount() || !sequence(row).transcriptProposed)
        return false;
    const TranscriptState before{QString::fromStdString(sequence(row).transcript), true,
                                 sequence(row).transcriptConfidence};
    m_undo->push(new SetTranscriptCommand(this, row, before, TranscriptState{before.text, false, {}},
                                          SetTranscriptCommand::Kind::Accept));
    return true;
}

void ProjectDocument::applyTranscript(int row, const TranscriptState &state)
{
    Sequence &s = m_project.sequences.at(std::size_t(row));
    s.transcript = state.text.toStdString();
    s.transcriptProposed = state.proposed;
    s.transcriptConfidence = state.confidence;
    emit sequenceChanged(row);
}

bool ProjectDocument::requestTiersChange(int row, const Tier &words, const Tier &phones, const QString &text,
                                         int mergeKey)
{
    if (row < 0 || row >= sequenceCount())
        return false;
    return pushTiers(row, TierPair{words, phones, sequence(row).transcriptFit}, text, mergeKey);
}

bool ProjectDocument::requestAlignedTiers(int row, const TierPair &aligned, const QString &text)
{
    if (row < 0 || row >= sequenceCount())
        return false;
    return pushTiers(row, aligned, text, -1);
}

bool ProjectDocument::pushTiers(int row, TierPair after, const QString &text, int mergeKey)
{
    const Sequence &s = sequence(row);
    TierPair before{s.words, s.phones, s.transcriptFit};
    after.words.name = "words";
    after.phones.name = "phones";
    if (before == after)
        return false;
    // Every command leaves a document that saves and loads again (Tier::defect is the loader's
    // rule): an edit that would break it is refused whole, never half applied.
    for (const Tier *tier : {&after.words, &after.phones})
        if (const std::optional<TierDefect> d = tier->defect()) {
            refuse(text, tr("%1 interval %2: %3")
                             .arg(QString::fromStdString(tier->name))
                             .arg(d->index + 1)
                             .arg(QString::fromStdString(d->member + " " + d->message)));
            return false;
        }
    m_undo->push(new SetTiersCommand(this, row, std::move(before), std::move(after), text, mergeKey));
    return true;
}

void ProjectDocument::applyTiers(int row, const TierPair &tiers)
{
    Sequence &s = m_project.sequences.at(std::size_t(row));
    s.words = tiers.words;
    s.phones = tiers.phones;
    s.transcriptFit = tiers.transcriptFit;
    emit sequenceChanged(row);
}

void ProjectDocument::refuse(const QString &edit, const QString &why)
{
    qWarning().noquote() << "edit refused:" << edit << "-" << why;
    emit editRefused(edit, why);
}

bool ProjectDocument::requestLandmarks(int row, int frame, const std::optional<LandmarkSet> &landmarks,
                                       const QString &text)
{
    if (row < 0 || row >= sequenceCount() || frame < 0)
        return false;
    const Sequence &s = sequence(row);
    const auto it = s.landmarks.find(frame);
    std::optional<LandmarkSet> before;
    if (it != s.landmarks.end())
        before = it->second;
    if (before == landmarks)
        return false;
    m_undo->push(new SetLandmarksCommand(this, row, frame, before, landmarks, text));
    return true;
}

void ProjectDocument::applyLandmarks(int row, int frame, const std::optional<LandmarkSet> &landmarks)
{
    Sequence &s = m_project.sequences.at(std::size_t(row));
    if (landmarks)
        s.landmarks[frame] = *landmarks;
    else
        s.landmarks.erase(frame);
    emit sequenceChanged(row);
}

bool ProjectDocument::requestFaces(const std::vector<FaceData> &faces, const QString &text)
{
    std::vector<FaceData> before;
    for (const FaceData &f : faces) {
        if (f.row < 0 || f.row >= sequenceCount())
            return false;
        const Sequence &s = sequence(f.row);
        before.push_back({f.row, s.landmarks, s.features, s.fitErrors});
    }
    if (faces.empty())
        return false;
    m_undo->push(new SetFacesCommand(this, std::move(before), faces, text));
    return true;
}

void ProjectDocument::applyFaces(const std::vector<FaceData> &faces)
{
    for (const FaceData &f : faces) {
        Sequence &s = m_project.sequences.at(std::size_t(f.row));
        s.landmarks = f.landmarks;
        s.features = f.features;
        s.fitErrors = f.fitErrors;
    }
    for (const FaceData &f : faces)
        emit sequenceChanged(f.row);
}

bool ProjectDocument::requestAddModel(const ModelReference &model, const QString &text)
{
    std::vector<ModelReference> after = m_project.models;
    const auto same = std::find_if(after.begin(), after.end(), [&](const ModelReference &m) {
        return m.kind == model.kind && m.name == model.name;
    });
    if (same != after.end())
        *same = model;
    else
        after.push_back(model);
    m_undo->push(new SetModelsCommand(this, m_project.models, std::move(after), text));
    return true;
}

bool ProjectDocument::requestPronunciations(const std::map<std::string, std::string> &pronunciations,
                                            const QString &text)
{
    if (!m_open || pronunciations == m_project.pronunciations)
        return false;
    m_undo->push(new SetPronunciationsCommand(this, m_project.pronunciations, pronunciations, text));
    return true;
}

void ProjectDocument::applyPronunciations(const std::map<std::string, std::string> &pronunciations)
{
    m_project.pronunciations = pronunciations;
    emit pronunciationsChanged();
}

bool ProjectDocument::requestMouthShapes(const std::map<std::string, Project::MouthShapeFeatures> &shapes,
                                         const QString &text, int mergeKey)
{
    if (!m_open || shapes == m_project.mouthShapes)
        return false;
    m_undo->push(new SetMouthShapesCommand(this, m_project.mouthShapes, shapes, text, mergeKey));
    return true;
}

void ProjectDocument::applyMouthShapes(const std::map<std::string, Project::MouthShapeFeatures> &shapes)
{
    m_project.mouthShapes = shapes;
    emit mouthShapesChanged();
}

void ProjectDocument::applyModels(const std::vector<ModelReference> &models)
{
    m_project.models = models;
    emit modelsChanged();
}

bool ProjectDocument::requestStudy(const std::optional<ForcedChoiceStudy> &study, const QString &text)
{
    if (study == m_project.study)
        return false;
    m_undo->push(new SetStudyCommand(this, m_project.study, study, text));
    return true;
}

void ProjectDocument::applyStudy(const std::optional<ForcedChoiceStudy> &study)
{
    m_project.study = study;
    emit studyChanged();
}

bool ProjectDocument::isStudySaved() const
{
    return m_open && !m_readOnly && !m_folder.isEmpty() && m_project.study && !isModified()
           && QFileInfo::exists(QString::fromStdString(m_project.studyPath()));
}

void ProjectDocument::recordStudyData(ForcedChoiceStudy study)
{
    // Written before it is taken: if the disk refuses, the answer is not pretended.
    if (isStudySaved()) {
        Project copy = m_project;
        copy.study = study;
        copy.saveStudy();
    } else {
        m_unsavedStudyData = true; // the next save writes it; closing asks first
    }
    m_project.study = std::move(study);
    emit studyChanged();
}

int ProjectDocument::addStudyParticipant(const QString &participant)
{
    if (!m_project.study)
        throw Error("the project has no study");
    ForcedChoiceStudy study = *m_project.study;
    study.addParticipant(participant.toStdString());
    const int session = int(study.sessions().size()) - 1;
    recordStudyData(std::move(study));
    return session;
}

void ProjectDocument::recordStudyAnswer(int session, int trial, StudyChoice choice, double seconds)
{
    if (!m_project.study)
        throw Error("the project has no study");
    ForcedChoiceStudy study = *m_project.study;
    study.answer(session, trial, choice, seconds);
    recordStudyData(std::move(study));
}

} // namespace lipsync::studio
