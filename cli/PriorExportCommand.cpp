// lipsync export prior --project DIR --out FILE: the mouth prior of a project's speaker(s)
// (animation/MouthShapePrior) for `train --kind hmm --prior-file` on a person with little footage;
// the shipped resources/prior/grid-s1.mouthprior is this on GRID s1's 400 clips.
#include "CommandLine.h"

#include "aam/AamModel.h"
#include "animation/MouthMeasures.h"
#include "animation/MouthShapePrior.h"
#include "animation/MouthTrack.h"
#include "project/Project.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QJsonObject>

#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

int runExportPrior(const CommandLine &args)
{
    const Project project = Project::load(args.value(QStringLiteral("project")).toStdString());
    const AamModel model = AamModel::load(project.aamPath());
    const MouthMeasurer measurer(model);
    const std::vector<MouthTrack> tracks = projectMouthTracks(measurer, project);
    const MouthShapePrior prior = MouthShapePrior::learn(tracks);
    const QString out = args.value(QStringLiteral("out"));
    prior.save(out.toStdString());
    int phones = 0;
    for (int p = 0; p < PhoneSet::kCount; ++p)
        phones += prior.frames()(p) > 0;
    if (args.isSet(QStringLiteral("json")))
        printJson(QJsonObject{{QStringLiteral("out"), out},
                              {QStringLiteral("sequences"), int(tracks.size())},
                              {QStringLiteral("frames"), prior.frames().sum()},
                              {QStringLiteral("phones"), phones}});
    else
        std::printf("mouth prior from %zu sequences (%.0f frames, %d phones) -> %s\n", tracks.size(),
                    prior.frames().sum(), phones, out.toUtf8().constData());
    return 0;
}

const CommandRegistration registration{
    CommandSpec{QStringLiteral("export prior"),
                QStringLiteral("mouth shapes per phone learnt from a project's speakers, a starting point for people "
                               "with little footage"),
                QStringLiteral("Learns each phone's mouth, free of head pose, from a project's tracked and aligned "
                               "sequences, for `lipsync train --kind hmm --prior-file FILE` on another person's "
                               "project."),
                {{QStringLiteral("project"), QStringLiteral("DIR"), QStringLiteral("the project to learn from"), {},
                  CommandOption::Required},
                 {QStringLiteral("out"), QStringLiteral("FILE"), QStringLiteral("the prior to write (.mouthprior)"), {},
                  CommandOption::Required}},
                {}},
    &runExportPrior};

} // namespace
