// For the tests: the instruction-set path forced for a scope, and the one in
// use before put back when it ends (render/isa.hpp).
#pragma once

#include "render/isa.hpp"

namespace promyk {

struct PathForced {
    Isa before = article_isa();
    explicit PathForced(Isa isa) { set_article_isa(isa); }
    ~PathForced() { set_article_isa(before); }
};

}  // namespace promyk
