#include "dynamics/ModelKind.h"

namespace lipsync {

const std::vector<ModelKind> &allModelKinds()
{
    static const std::vector<ModelKind> kinds{ModelKind::HmmMean, ModelKind::Brand, ModelKind::Slds,
                                              ModelKind::Dpds};
    return kinds;
}

const std::vector<std::string> &dynamicModelKinds()
{
    static const std::vector<std::string> ids = [] {
        std::vector<std::string> out;
        for (ModelKind kind : allModelKinds())
            out.emplace_back(modelKindId(kind));
        return out;
    }();
    return ids;
}

const char *modelKindId(ModelKind kind)
{
    switch (kind) {
    case ModelKind::HmmMean:
        return "hmm";
    case ModelKind::Brand:
        return "brand";
    case ModelKind::Slds:
        return "slds";
    case ModelKind::Dpds:
        return "dpds";
    }
    return "";
}

std::optional<ModelKind> parseModelKind(std::string_view id)
{
    for (ModelKind kind : allModelKinds())
        if (id == modelKindId(kind))
            return kind;
    return std::nullopt;
}

bool isDynamicModelKind(std::string_view id)
{
    return parseModelKind(id).has_value();
}

bool modelKindTakesPrior(ModelKind kind)
{
    return kind == ModelKind::HmmMean || kind == ModelKind::Brand;
}

std::string modelKindIdList(std::string_view lastSeparator, std::string_view separator)
{
    const std::vector<ModelKind> &kinds = allModelKinds();
    std::string out;
    for (size_t i = 0; i < kinds.size(); ++i) {
        if (i > 0)
            out += i + 1 == kinds.size() ? lastSeparator : separator;
        out += modelKindId(kinds[kinds.size() - 1 - i]);
    }
    return out;
}

} // namespace lipsync
