#include "project/ForcedChoiceStudy.h"

#include "project/Project.h"

#include "util/Error.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>

#include <algorithm>
#include <limits>
#include <random>
#include <set>

namespace lipsync {

namespace {

// SplitMix64 (Steele et al. 2014): decorrelates the per-session seeds drawn from one study seed.
std::uint64_t splitMix64(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// Uniform integer in [0, bound) by rejection: std::uniform_int_distribution is not specified
// bit-for-bit, and a stored design must be reproducible on every standard library.
std::uint64_t uniformBelow(std::mt19937_64 &rng, std::uint64_t bound)
{
    const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max()
                                - std::numeric_limits<std::uint64_t>::max() % bound;
    std::uint64_t x;
    do
        x = rng();
    while (x >= limit);
    return x % bound;
}

template <typename T>
void shuffle(std::vector<T> &items, std::mt19937_64 &rng)
{
    for (size_t i = items.size(); i > 1; --i)
        std::swap(items[i - 1], items[size_t(uniformBelow(rng, i))]);
}

StudyChoice choiceFromName(const QString &name, bool *ok)
{
    *ok = true;
    if (name == QLatin1String("left"))
        return StudyChoice::Left;
    if (name == QLatin1String("right"))
        return StudyChoice::Right;
    if (name == QLatin1String("undecided"))
        return StudyChoice::Undecided;
    if (name.isEmpty())
        return StudyChoice::Unanswered;
    *ok = false;
    return StudyChoice::Unanswered;
}

std::vector<std::string> stringList(const QJsonValue &value, const std::string &source,
                                    const std::string &field)
{
    if (!value.isArray())
        throw Error("must be an array of strings", source, field);
    std::vector<std::string> out;
    for (const QJsonValue &item : value.toArray()) {
        if (!item.isString())
            throw Error("must be an array of strings", source, field);
        out.push_back(item.toString().toStdString());
    }
    return out;
}

std::uint64_t seedFrom(const QJsonValue &value, const std::string &source, const std::string &field)
{
    // Stored as a decimal string: JSON numbers are doubles and cannot hold 64 bits.
    bool ok = false;
    const std::uint64_t seed = value.toString().toULongLong(&ok);
    if (!value.isString() || !ok)
        throw Error("must be an unsigned integer in a string", source, field);
    return seed;
}

} // namespace

std::string studyChoiceName(StudyChoice choice)
{
    switch (choice) {
    case StudyChoice::Left:
        return "left";
    case StudyChoice::Right:
        return "right";
    case StudyChoice::Undecided:
        return "undecided";
    case StudyChoice::Unanswered:
        break;
    }
    return {};
}

int StudySession::answered() const
{
    return int(std::count_if(trials.begin(), trials.end(), [](const StudyTrial &t) {
        return t.choice != StudyChoice::Unanswered;
    }));
}

int StudySession::nextTrial() const
{
    for (size_t i = 0; i < trials.size(); ++i)
        if (trials[i].choice == StudyChoice::Unanswered)
            return int(i);
    return -1;
}

ForcedChoiceStudy::ForcedChoiceStudy(std::vector<std::string> methods,
                                     std::vector<std::string> utterances, std::uint64_t seed,
                                     int repeats)
    : m_methods(std::move(methods)), m_utterances(std::move(utterances)), m_seed(seed),
      m_repeats(repeats)
{
    if (m_methods.size() < 2)
        throw Error("a study compares at least two methods");
    std::set<std::string> distinct;
    for (const std::string &m : m_methods)
        if (m.empty() || !distinct.insert(m).second)
            throw Error("method names must be non-empty and distinct (\"" + m + "\")");
    if (m_utterances.empty())
        throw Error("a study needs at least one utterance");
    for (const std::string &u : m_utterances)
        if (u.empty())
            throw Error("utterance names must be non-empty");
    if (m_repeats < 1)
        throw Error("repeats must be at least 1");
}

int ForcedChoiceStudy::trialsPerSession() const
{
    const int m = int(m_methods.size());
    return m * (m - 1) * m_repeats;
}

StudySession &ForcedChoiceStudy::addParticipant(const std::string &participant)
{
    if (participant.empty())
        throw Error("a participant needs a pseudonym");
    for (const StudySession &s : m_sessions)
        if (s.participant == participant)
            throw Error("participant \"" + participant + "\" already has a session");

    StudySession session;
    session.participant = participant;
    session.seed = splitMix64(m_seed ^ splitMix64(m_sessions.size() + 1));
    std::mt19937_64 rng(session.seed);

    // Every ordered pair (i, j), i != j, `repeats` times: each unordered pair twice per repeat,
    // once per side, so every method sits on the left and on the right equally often.
    const int m = int(m_methods.size());
    for (int r = 0; r < m_repeats; ++r)
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j)
                if (i != j)
                    session.trials.push_back(StudyTrial{i, j, {}, StudyChoice::Unanswered, -1});
    shuffle(session.trials, rng);

    // Utterances are dealt from a shuffled deck, reshuffled when used up: a participant sees as
    // many different sentences as the pool allows, and each trial's sentence is random.
    std::vector<std::string> deck;
    for (StudyTrial &trial : session.trials) {
        if (deck.empty()) {
            deck = m_utterances;
            shuffle(deck, rng);
        }
        trial.utterance = deck.back();
        deck.pop_back();
    }
    m_sessions.push_back(std::move(session));
    return m_sessions.back();
}

void ForcedChoiceStudy::answer(int session, int trial, StudyChoice choice, double responseSeconds)
{
    if (session < 0 || session >= int(m_sessions.size()))
        throw Error("no study session " + std::to_string(session));
    StudySession &s = m_sessions[size_t(session)];
    if (trial < 0 || trial >= int(s.trials.size()))
        throw Error("session \"" + s.participant + "\" has no trial " + std::to_string(trial));
    s.trials[size_t(trial)].choice = choice;
    s.trials[size_t(trial)].responseSeconds = responseSeconds;
}

std::vector<std::string> ForcedChoiceStudy::candidateUtterances(const Project &project)
{
    std::vector<std::string> ids;
    for (const Sequence &s : project.sequences)
        if (s.features.rows() > 0 && !s.phones.isEmpty())
            ids.push_back(s.id);
    return ids;
}

std::vector<std::string> ForcedChoiceStudy::drawUtterances(std::vector<std::string> pool, int count,
                                                           std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::vector<size_t> order(pool.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    for (size_t i = order.size(); i > 1; --i)
        std::swap(order[i - 1], order[size_t(rng() % i)]);
    order.resize(std::min(order.size(), size_t(std::max(count, 0))));
    std::sort(order.begin(), order.end());
    std::vector<std::string> drawn;
    for (size_t i : order)
        drawn.push_back(pool[i]);
    return drawn;
}

int ForcedChoiceStudy::defaultHeldOutCount(int candidates)
{
    return std::max(1, std::min(candidates / 5, candidates - 1));
}

QJsonObject ForcedChoiceStudy::toJson() const
{
    auto strings = [](const std::vector<std::string> &list) {
        QJsonArray array;
        for (const std::string &s : list)
            array.append(QString::fromStdString(s));
        return array;
    };
    QJsonArray sessions;
    for (const StudySession &s : m_sessions) {
        QJsonArray trials;
        for (const StudyTrial &t : s.trials) {
            QJsonObject trial{{"left", QString::fromStdString(m_methods[size_t(t.left)])},
                              {"right", QString::fromStdString(m_methods[size_t(t.right)])},
                              {"utterance", QString::fromStdString(t.utterance)}};
            trial["choice"] = t.choice == StudyChoice::Unanswered
                                  ? QJsonValue(QJsonValue::Null)
                                  : QJsonValue(QString::fromStdString(studyChoiceName(t.choice)));
            if (t.responseSeconds >= 0)
                trial["seconds"] = t.responseSeconds;
            trials.append(trial);
        }
        sessions.append(QJsonObject{{"participant", QString::fromStdString(s.participant)},
                                    {"seed", QString::number(s.seed)},
                                    {"trials", trials}});
    }
    return QJsonObject{{"format", kFormatName},
                       {"version", kFormatVersion},
                       {"methods", strings(m_methods)},
                       {"utterances", strings(m_utterances)},
                       {"seed", QString::number(m_seed)},
                       {"repeats", m_repeats},
                       {"holdOutUtterances", m_holdOut},
                       {"sessions", sessions}};
}

ForcedChoiceStudy ForcedChoiceStudy::fromJson(const QJsonObject &json, const std::string &source)
{
    if (json.value("format").toString() != QLatin1String(kFormatName))
        throw Error(std::string("not a forced-choice study (expected \"format\": \"") + kFormatName
                        + "\")",
                    source, "format");
    if (json.value("version").toInt(-1) != kFormatVersion)
        throw Error("unsupported version (this program reads version "
                        + std::to_string(kFormatVersion) + ")",
                    source, "version");
    const int repeats = json.value("repeats").toInt(0);
    if (repeats < 1)
        throw Error("must be a positive integer", source, "repeats");
    std::vector<std::string> methods = stringList(json.value("methods"), source, "methods");
    std::vector<std::string> utterances = stringList(json.value("utterances"), source, "utterances");
    const std::uint64_t seed = seedFrom(json.value("seed"), source, "seed");

    ForcedChoiceStudy study = [&] {
        try {
            return ForcedChoiceStudy(methods, utterances, seed, repeats);
        } catch (const Error &e) {
            throw Error(e.reason(), source, "methods");
        }
    }();
    const QJsonValue holdOut = json.value("holdOutUtterances");
    if (!holdOut.isUndefined() && !holdOut.isBool())
        throw Error("must be true or false", source, "holdOutUtterances");
    study.setHoldsOutUtterances(holdOut.toBool(false));
    auto methodIndex = [&](const QJsonValue &value, const std::string &field) {
        const auto it = std::find(methods.begin(), methods.end(), value.toString().toStdString());
        if (!value.isString() || it == methods.end())
            throw Error("unknown method \"" + value.toString().toStdString() + "\"", source, field);
        return int(it - methods.begin());
    };

    const QJsonValue sessionsValue = json.value("sessions");
    if (!sessionsValue.isArray())
        throw Error("must be an array", source, "sessions");
    const QJsonArray sessions = sessionsValue.toArray();
    std::set<std::string> participants;
    for (qsizetype si = 0; si < sessions.size(); ++si) {
        const std::string sessionField = "sessions[" + std::to_string(si) + "]";
        const QJsonObject s = sessions[si].toObject();
        StudySession session;
        session.participant = s.value("participant").toString().toStdString();
        if (session.participant.empty() || !participants.insert(session.participant).second)
            throw Error("missing or duplicate pseudonym", source, sessionField + ".participant");
        session.seed = seedFrom(s.value("seed"), source, sessionField + ".seed");
        if (!s.value("trials").isArray())
            throw Error("must be an array", source, sessionField + ".trials");
        const QJsonArray trials = s.value("trials").toArray();
        for (qsizetype ti = 0; ti < trials.size(); ++ti) {
            const std::string field = sessionField + ".trials[" + std::to_string(ti) + "]";
            const QJsonObject t = trials[ti].toObject();
            StudyTrial trial;
            trial.left = methodIndex(t.value("left"), field + ".left");
            trial.right = methodIndex(t.value("right"), field + ".right");
            if (trial.left == trial.right)
                throw Error("a method is compared with itself", source, field);
            trial.utterance = t.value("utterance").toString().toStdString();
            if (trial.utterance.empty())
                throw Error("missing utterance", source, field + ".utterance");
            const QJsonValue choice = t.value("choice");
            bool ok = choice.isNull() || choice.isUndefined() || choice.isString();
            if (ok && choice.isString())
                trial.choice = choiceFromName(choice.toString(), &ok);
            if (!ok)
                throw Error("must be \"left\", \"right\", \"undecided\" or null", source,
                            field + ".choice");
            trial.responseSeconds = t.value("seconds").toDouble(-1);
            session.trials.push_back(std::move(trial));
        }
        study.m_sessions.push_back(std::move(session));
    }
    return study;
}

void ForcedChoiceStudy::save(const std::string &path) const
{
    QSaveFile file(QString::fromStdString(path));
    const QByteArray text = QJsonDocument(toJson()).toJson(QJsonDocument::Indented);
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size() || !file.commit())
        throw Error("cannot write the study: " + file.errorString().toStdString(), path);
}

ForcedChoiceStudy ForcedChoiceStudy::load(const std::string &path)
{
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly))
        throw Error("cannot read the study: " + file.errorString().toStdString(), path);
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(file.readAll(), &parseError);
    if (parseError.error != QJsonParseError::NoError)
        throw Error("not valid JSON at offset " + std::to_string(parseError.offset) + ": "
                        + parseError.errorString().toStdString(),
                    path);
    if (!document.isObject())
        throw Error("the study must be a JSON object", path);
    return fromJson(document.object(), path);
}

} // namespace lipsync
