// Whether the article's rows skip the columns proven background
// (render/silhouette.hpp). On by default; bench speed turns it off for a
// run of its own, to time the kernel on every pixel beside the skipping run.
#pragma once

namespace promyk {

bool background_skipping();
// Not while rows are drawn.
void set_background_skipping(bool on);

}  // namespace promyk
