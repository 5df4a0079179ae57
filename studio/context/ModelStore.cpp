#include "context/ModelStore.h"

#include "aam/AamModel.h"
#include "document/ProjectDocument.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/ModelFile.h"
#include "dynamics/ModelKind.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>
#include <QStringList>

namespace lipsync::studio {

ModelStore::ModelStore(ProjectDocument *document, QObject *parent) : QObject(parent), m_document(document)
{
    connect(document, &ProjectDocument::documentReset, this, &ModelStore::onDocumentReset);
    connect(document, &ProjectDocument::locationChanged, this, &ModelStore::onLocationChanged);
}

ModelStore::~ModelStore() = default;

ModelStore::Entry *ModelStore::entryFor(const std::string &kind, QString *problem)
{
    const Project &project = m_document->project();
    const ModelReference *ref = project.model(kind);
    if (!ref)
        return nullptr;
    if (const auto it = m_entries.find(ref->file); it != m_entries.end())
        return &it->second;
    if (const auto it = m_failed.find(ref->file); it != m_failed.end()) {
        if (problem)
            *problem = it->second;
        return nullptr;
    }
    const std::string path = project.resolve(ref->file);
    try {
        Entry entry;
        if (kind == "aam")
            entry.aam = std::make_shared<const AamModel>(AamModel::load(path));
        else
            entry.dynamic = loadModel(path, {}, &entry.aamIdentifier);
        return &m_entries.emplace(ref->file, std::move(entry)).first->second;
    } catch (const std::exception &e) {
        // Not tried again for this document: a damaged file is reported once, not per redraw.
        const QString why = QString::fromUtf8(e.what());
        m_failed.emplace(ref->file, why);
        if (problem)
            *problem = why;
        return nullptr;
    }
}

std::shared_ptr<const AamModel> ModelStore::aam(QString *problem)
{
    const Entry *entry = entryFor("aam", problem);
    return entry ? entry->aam : nullptr;
}

std::shared_ptr<const DynamicModel> ModelStore::dynamicModel(const QString &kind, QString *problem)
{
    const Entry *entry = entryFor(kind.toStdString(), problem);
    return entry ? entry->dynamic : nullptr;
}

std::string ModelStore::aamIdentifier()
{
    const auto model = aam();
    return model ? model->identifier : std::string(kUnspecifiedAam);
}

std::string ModelStore::recordedAamIdentifier(const QString &kind)
{
    const Entry *entry = entryFor(kind.toStdString(), nullptr);
    return entry ? entry->aamIdentifier : std::string();
}

QString ModelStore::reserveFile(const QString &kind)
{
    const bool isAam = kind == QLatin1String("aam");
    const QString stem = isAam ? QStringLiteral("aam/faces") : QStringLiteral("models/") + kind;
    const QString suffix = isAam                                 ? QStringLiteral(".aam")
                           : kind == QLatin1String("aligner") ? QStringLiteral(".aligner")
                                                              : QStringLiteral(".model");
    const Project &project = m_document->project();
    for (int n = 1;; ++n) {
        const QString file = n == 1 ? stem + suffix : QStringLiteral("%1-%2%3").arg(stem).arg(n).arg(suffix);
        const std::string f = file.toStdString();
        bool taken = m_entries.count(f) || m_reserved.count(f) || m_failed.count(f);
        for (const ModelReference &m : project.models)
            taken = taken || m.file == f;
        taken = taken || (!project.folder().empty() && QFileInfo::exists(QString::fromStdString(project.resolve(f))));
        if (!taken) {
            m_reserved.insert(f);
            return file;
        }
    }
}

void ModelStore::releaseFile(const QString &file)
{
    if (!m_entries.count(file.toStdString()))
        m_reserved.erase(file.toStdString());
}

bool ModelStore::hasWritableFolder() const
{
    return !m_document->isReadOnly() && !m_document->folder().isEmpty();
}

QString ModelStore::writablePath(const QString &file) const
{
    return hasWritableFolder() ? QDir(m_document->folder()).filePath(file) : QString();
}

void ModelStore::addAam(const QString &file, std::shared_ptr<const AamModel> model, bool written)
{
    Entry &entry = m_entries[file.toStdString()];
    entry = Entry{std::move(model), nullptr, {}, !written};
    m_failed.erase(file.toStdString());
}

QString ModelStore::addDynamicModel(const QString &file, std::shared_ptr<const DynamicModel> model,
                                    const std::string &aamIdentifier)
{
    Entry &entry = m_entries[file.toStdString()];
    entry = Entry{nullptr, std::move(model), aamIdentifier, true};
    m_failed.erase(file.toStdString());
    const QString path = writablePath(file);
    if (path.isEmpty())
        return {};
    try {
        QDir().mkpath(QFileInfo(path).absolutePath());
        saveModel(*entry.dynamic, path.toStdString(), aamIdentifier);
        entry.unwritten = false;
        return {};
    } catch (const Error &e) {
        return QString::fromUtf8(e.what());
    }
}

bool ModelStore::isUnwritten(const std::string &file) const
{
    const auto it = m_entries.find(file);
    return it != m_entries.end() && it->second.unwritten;
}

void ModelStore::onDocumentReset()
{
    m_entries.clear();
    m_reserved.clear();
    m_failed.clear();
}

void ModelStore::onLocationChanged()
{
    // The project has a folder of its own now (Save As): every model held here that the folder
    // lacks goes there — those made in the demo, and earlier ones an undo can bring back.
    if (!hasWritableFolder())
        return; // still read-only
    QStringList problems;
    for (auto &[file, entry] : m_entries) {
        const QString path = writablePath(QString::fromStdString(file));
        if (QFileInfo::exists(path) && !entry.unwritten)
            continue;
        try {
            QDir().mkpath(QFileInfo(path).absolutePath());
            if (entry.aam)
                entry.aam->save(path.toStdString());
            else if (entry.dynamic)
                saveModel(*entry.dynamic, path.toStdString(), entry.aamIdentifier);
            entry.unwritten = false;
        } catch (const std::exception &e) {
            problems << QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(path), QString::fromUtf8(e.what()));
        }
    }
    if (!problems.isEmpty())
        emit writeFailed(problems.join(QLatin1Char('\n')));
}

} // namespace lipsync::studio
