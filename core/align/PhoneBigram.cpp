#include "align/PhoneBigram.h"

#include "io/AtomicFile.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace lipsync {

namespace {

constexpr int P = PhoneSet::kCount;
constexpr const char *kHeader = "lipsync-phone-bigram";
constexpr double kMaxCount = 1e15; // exact in a double

} // namespace

PhoneBigram::PhoneBigram() : PhoneBigram(Eigen::MatrixXd::Zero(P, P)) {}

PhoneBigram::PhoneBigram(const Eigen::MatrixXd &counts) : m_counts(counts), m_log(P, P)
{
    for (int p = 0; p < P; ++p) {
        const double total = m_counts.row(p).sum() + P;
        for (int q = 0; q < P; ++q)
            m_log(p, q) = std::log((m_counts(p, q) + 1.0) / total);
    }
}

PhoneBigram PhoneBigram::fromTiers(const std::vector<Tier> &phoneTiers)
{
    Eigen::MatrixXd counts = Eigen::MatrixXd::Zero(P, P);
    for (size_t k = 0; k < phoneTiers.size(); ++k) {
        int previous = PhoneSet::kSilence;
        for (const Interval &i : phoneTiers[k].intervals) {
            const int phone = i.label.empty() ? int(PhoneSet::kSilence) : PhoneSet::index(i.label);
            if (phone < 0)
                throw Error("phone tier " + std::to_string(k + 1) + " has \"" + i.label
                            + "\", which is not one of the 41 phones");
            counts(previous, phone) += 1.0;
            previous = phone;
        }
    }
    return PhoneBigram(counts);
}

std::string PhoneBigram::text() const
{
    std::string out = std::string(kHeader) + " " + std::to_string(kFormatVersion) + "\n";
    char number[32];
    for (int p = 0; p < P; ++p) {
        for (int q = 0; q < P; ++q) {
            std::snprintf(number, sizeof number, q ? " %.0f" : "%.0f", m_counts(p, q));
            out += number;
        }
        out += '\n';
    }
    return out;
}

void PhoneBigram::save(const std::string &path) const
{
    writeFileAtomically(path, text());
}

PhoneBigram PhoneBigram::load(const std::string &path)
{
    return parse(readWholeFile(path), path);
}

PhoneBigram PhoneBigram::parse(const std::string &text, const std::string &pathForErrors)
{
    std::istringstream in(text);
    std::string header;
    int version = 0;
    if (!(in >> header >> version) || header != kHeader)
        throw Error("not a phone bigram file (no \"lipsync-phone-bigram\" header)", pathForErrors);
    if (version != kFormatVersion)
        throw Error("phone bigram version " + std::to_string(version) + " is not supported", pathForErrors);
    std::string line;
    std::getline(in, line);
    Eigen::MatrixXd counts(P, P);
    for (int p = 0; p < P; ++p) {
        if (!std::getline(in, line))
            throw Error("line " + std::to_string(p + 2) + ": missing (41 rows of counts expected)", pathForErrors);
        std::istringstream row(line);
        for (int q = 0; q < P; ++q) {
            double c = -1.0;
            if (!(row >> c) || !(c >= 0) || c > kMaxCount || c != std::floor(c))
                throw Error("line " + std::to_string(p + 2) + ": 41 whole counts >= 0 expected", pathForErrors);
            counts(p, q) = c;
        }
        std::string extra;
        if (row >> extra)
            throw Error("line " + std::to_string(p + 2) + ": more than 41 counts", pathForErrors);
    }
    return PhoneBigram(counts);
}

} // namespace lipsync
