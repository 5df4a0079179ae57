// Child process of tst_projectcrash: saves the project in argv[1] over and over, each save a new
// version k whose name ("v<k>"), transcripts and features (k in every cell, 8 or 12 columns
// depending on k's parity) all say k, so a reader can tell a mix of two versions from either.
// Starts from the version on disk (if any), so versions only grow across kills.
#include "project/Project.h"

#include <cstdio>
#include <string>

using namespace lipsync;

namespace {

void setVersion(Project &project, int k)
{
    project.name = "v" + std::to_string(k);
    for (Sequence &s : project.sequences) {
        s.transcript = project.name;
        s.features = Eigen::MatrixXd::Constant(s.frameCount, k % 2 ? 8 : 12, double(k));
    }
}

} // namespace

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: ProjectSaveLoop FOLDER\n");
        return 2;
    }
    const std::string folder = argv[1];
    Project project;
    int k = 0;
    try {
        project = Project::load(folder);
        k = std::stoi(project.name.substr(1));
    } catch (const std::exception &) {
        for (int i = 0; i < 3; ++i) {
            Sequence s;
            s.id = "s" + std::to_string(i);
            s.mediaFile = "media/" + s.id + ".mpg";
            s.frameCount = 40;
            project.sequences.push_back(s);
        }
    }
    for (;;) {
        setVersion(project, ++k);
        project.save(folder);
        std::printf("saved %d\n", k); // the test kills only after a first save of its own
        std::fflush(stdout);
    }
}
