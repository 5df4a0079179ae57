// lipsync aligner bigram (--alignments DIR | --project DIR) --out FILE: the phone bigram of live
// recognition (align/PhoneBigram), counted from forced alignments: the "phones" tiers of a
// folder of TextGrids (lipsync align DIR --out DIR) or of a project's sequences.
#include "CommandLine.h"

#include "align/PhoneBigram.h"
#include "io/TextGrid.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QDir>

#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

int runAlignerBigram(const CommandLine &a)
{
    if (a.isSet("alignments") == a.isSet("project"))
        throw UsageError(QStringLiteral("give either --alignments DIR or --project DIR"));
    std::vector<Tier> tiers;
    if (a.isSet("project")) {
        for (const Sequence &s : Project::load(a.value("project").toStdString()).sequences)
            if (!s.phones.isEmpty())
                tiers.push_back(s.phones);
    } else {
        const QDir dir(a.value("alignments"));
        if (!dir.exists())
            throw Error("no such folder", a.value("alignments").toStdString());
        for (const QString &name : dir.entryList({QStringLiteral("*.TextGrid")}, QDir::Files, QDir::Name)) {
            const std::string path = dir.filePath(name).toStdString();
            const TextGrid grid = readTextGrid(path);
            const Tier *phones = grid.tier("phones");
            if (!phones)
                throw Error("no \"phones\" tier", path);
            tiers.push_back(*phones);
        }
    }
    if (tiers.empty())
        throw Error("no phone alignments", (a.isSet("project") ? a.value("project") : a.value("alignments")).toStdString());
    const PhoneBigram bigram = PhoneBigram::fromTiers(tiers);
    bigram.save(a.value("out").toStdString());
    if (a.isSet("json"))
        printJson(QJsonObject{{QStringLiteral("alignments"), int(tiers.size())},
                              {QStringLiteral("transitions"), bigram.transitions()},
                              {QStringLiteral("out"), a.value("out")}});
    else
        std::printf("counted %.0f phone transitions in %zu alignments -> %s\n", bigram.transitions(), tiers.size(),
                    qPrintable(a.value("out")));
    return 0;
}

const CommandRegistration registration{
    CommandSpec{QStringLiteral("aligner bigram"),
                QStringLiteral("the phone bigram of live recognition, from forced alignments"),
                QStringLiteral("Counts which phone follows which in forced alignments (the \"phones\" tiers of a folder "
                               "of TextGrids, or of a project's sequences) and writes the bigram that `lipsync live` "
                               "and the studio's Live view recognise phones with (add-one smoothed)."),
                {{QStringLiteral("alignments"), QStringLiteral("DIR"),
                  QStringLiteral("a folder of TextGrids with a \"phones\" tier (lipsync align)")},
                 {QStringLiteral("project"), QStringLiteral("DIR"), QStringLiteral("instead: a project's alignments")},
                 {QStringLiteral("out"), QStringLiteral("FILE"), QStringLiteral("the bigram file to write"), {},
                  CommandOption::Required}},
                {}},
    &runAlignerBigram};

} // namespace
