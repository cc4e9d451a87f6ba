#include "cordgrasp/core/cord_params.h"

#include "cordgrasp/core/enum_names.h"

namespace cordgrasp {
namespace {

constexpr EnumName<SphereSequence> kSphereSequenceNames[] = {
    {SphereSequence::kYershovaLaValle, "yershova_lavalle"},
    {SphereSequence::kFibonacci, "fibonacci"}};
constexpr EnumName<CordConstruction> kCordConstructionNames[] = {
    {CordConstruction::kHullChain, "hull_chain"}, {CordConstruction::kTighten, "tighten"}};
constexpr EnumName<XorBackend> kXorBackendNames[] = {{XorBackend::kClipper, "clipper"},
                                                     {XorBackend::kConvex, "convex"}};
constexpr EnumName<SideCordPolicy> kSideCordPolicyNames[] = {
    {SideCordPolicy::kDiscardSet, "discard"},
    {SideCordPolicy::kShrink, "shrink"},
    {SideCordPolicy::kEmptyWhenMissed, "empty"},
    {SideCordPolicy::kFallback, "fallback"}};

}  // namespace

const char* to_string(SphereSequence s) { return enum_to_string(s, kSphereSequenceNames); }
SphereSequence parse_sphere_sequence(const std::string& text) {
  return parse_enum(text, kSphereSequenceNames, "sphere sequence");
}

const char* to_string(CordConstruction c) { return enum_to_string(c, kCordConstructionNames); }
CordConstruction parse_cord_construction(const std::string& text) {
  return parse_enum(text, kCordConstructionNames, "cord construction");
}

const char* to_string(XorBackend b) { return enum_to_string(b, kXorBackendNames); }
XorBackend parse_xor_backend(const std::string& text) {
  return parse_enum(text, kXorBackendNames, "XOR backend");
}

const char* to_string(SideCordPolicy p) { return enum_to_string(p, kSideCordPolicyNames); }
SideCordPolicy parse_side_cord_policy(const std::string& text) {
  return parse_enum(text, kSideCordPolicyNames, "side-cord policy");
}

}  // namespace cordgrasp
