// The lab's panel layout (ui/panel_layout.h) and the scatter plot's label placement (ui/label_placement.h):
// panels stay inside the window through resizes and come back when it grows; labels never overlap.
#include <gtest/gtest.h>

#include "ui/label_placement.h"
#include "ui/panel_layout.h"

namespace raylab {
namespace {

Box display(float w, float h) { return {0, 0, w, h}; }

TEST(PanelLayout, DefaultsAreInsideAndApartAtCommonSizes) {
  for (auto [w, h] : {std::pair{1280.0f, 720.0f}, {800.0f, 500.0f}, {1920.0f, 1080.0f}, {640.0f, 400.0f}}) {
    for (Panel a : kAllPanels) {
      Box b = defaultPanelBox(a, w, h);
      EXPECT_TRUE(b.inside(display(w, h))) << panelTitle(a) << " at " << w << "x" << h;
      EXPECT_GE(b.y1 - b.y0, 100.0f) << panelTitle(a) << " at " << w << "x" << h;  // more than a title bar
      for (Panel other : kAllPanels)
        if (other != a) {
          EXPECT_FALSE(b.overlaps(defaultPanelBox(other, w, h))) << panelTitle(a) << "/" << panelTitle(other);
        }
    }
  }
}

// The legend is docked between the columns: inside, over none of the default panels, wide enough for its
// ramp and the same box whatever the view (it depends on the display size only).
TEST(PanelLayout, HeatmapLegendOverlapsNoDefaultPanel) {
  for (auto [w, h] : {std::pair{1280.0f, 720.0f}, {800.0f, 500.0f}, {1920.0f, 1080.0f}, {640.0f, 400.0f}}) {
    Box legend = heatmapLegendBox(w, h);
    EXPECT_TRUE(legend.inside(display(w, h))) << w << "x" << h;
    EXPECT_GE(legend.x1 - legend.x0, 260.0f) << w << "x" << h;
    // Tall enough for its lines where the display allows, and never more than a tenth of it (issue 38: a
    // 480x300 legend hid most of the image between the panels at 1280x720).
    const float area = (legend.x1 - legend.x0) * (legend.y1 - legend.y0);
    EXPECT_LE(area, 0.1f * w * h) << w << "x" << h;
    EXPECT_GE(legend.y1 - legend.y0, std::min(150.0f, 0.09f * w * h / (legend.x1 - legend.x0))) << w << "x" << h;
    for (Panel p : kAllPanels)
      EXPECT_FALSE(legend.overlaps(defaultPanelBox(p, w, h))) << panelTitle(p) << " at " << w << "x" << h;
  }
}

TEST(PanelLayout, ShrinkKeepsPanelsInsideAndGrowingBringsThemBack) {
  PanelLayout layout;
  std::map<Panel, Box> at;
  for (Panel p : kAllPanels) at[p] = layout.keepInside(p, defaultPanelBox(p, 1280, 720), false, 1280, 720);
  for (auto [w, h] : {std::pair{800.0f, 500.0f}, {300.0f, 200.0f}, {160.0f, 90.0f}}) {
    for (Panel p : kAllPanels) {
      Box b = layout.keepInside(p, at[p], false, w, h);
      EXPECT_TRUE(b.inside(display(w, h))) << panelTitle(p) << " at " << w << "x" << h;
      at[p] = b;  // ImGui now has it there
    }
  }
  // Untouched panels follow the defaults of each size, so at 800x500 they do not pile over each other.
  for (Panel p : kAllPanels) at[p] = layout.keepInside(p, at[p], false, 800, 500);
  for (Panel p : kAllPanels)
    for (Panel q : kAllPanels)
      if (p != q) {
        EXPECT_FALSE(at[p].overlaps(at[q])) << panelTitle(p) << "/" << panelTitle(q);
      }
  for (Panel p : kAllPanels) at[p] = layout.keepInside(p, at[p], false, 1280, 720);
  for (Panel p : kAllPanels) {
    Box want = defaultPanelBox(p, 1280, 720);
    EXPECT_EQ(at[p].x0, want.x0) << panelTitle(p);
    EXPECT_EQ(at[p].y0, want.y0) << panelTitle(p);
    EXPECT_EQ(at[p].x1, want.x1) << panelTitle(p);
    EXPECT_EQ(at[p].y1, want.y1) << panelTitle(p);
  }
  ASSERT_EQ(layout.rects().size(), 4u * 6u);  // every call, since startFrame was never called
  layout.startFrame();
  EXPECT_TRUE(layout.rects().empty());
}

// A panel the user put at the right edge stays at the right edge; one moved off-screen comes back inside.
TEST(PanelLayout, UserPlacesAreAnchoredToTheNearestEdges) {
  PanelLayout layout;  // the first box is not the default: the user's (or imgui.ini's)
  Box first = layout.keepInside(Panel::Timing, {900, 500, 1270, 710}, false, 1280, 720);
  EXPECT_EQ(first.x0, 900);
  Box wider = layout.keepInside(Panel::Timing, first, false, 1600, 900);
  EXPECT_EQ(wider.x1, 1590);
  EXPECT_EQ(wider.y1, 890);
  Box dragged = layout.keepInside(Panel::Timing, {1500, -40, 1870, 170}, false, 1600, 900);
  EXPECT_TRUE(dragged.inside(display(1600, 900)));
  EXPECT_EQ(dragged.x1, 1600);
  EXPECT_EQ(dragged.y0, 0);
}

TEST(PanelLayout, CollapsedPanelsKeepTheirSizeForLater) {
  PanelLayout layout;
  Box open = defaultPanelBox(Panel::SceneCamera, 1280, 720);
  layout.keepInside(Panel::SceneCamera, open, false, 1280, 720);
  Box titleBar{open.x0, open.y0, open.x1, open.y0 + 19};
  Box collapsed = layout.keepInside(Panel::SceneCamera, titleBar, true, 1280, 720);
  EXPECT_EQ(collapsed.y1 - collapsed.y0, 19);
  Box small = layout.keepInside(Panel::SceneCamera, collapsed, true, 800, 500);
  EXPECT_TRUE(small.inside(display(800, 500)));
  EXPECT_EQ(small.y1 - small.y0, 19);
}

TEST(PanelLayout, RectsJsonNamesEveryPanel) {
  PanelLayout layout;
  for (Panel p : kAllPanels) layout.keepInside(p, defaultPanelBox(p, 800, 500), false, 800, 500);
  nlohmann::json j = panelRectsJson(layout.rects(), 800, 500);
  ASSERT_EQ(j["rects"].size(), 4u);
  EXPECT_EQ(j["rects"][3]["title"], "Scene and camera");
  EXPECT_EQ(j["display"][0], 800);
  EXPECT_FALSE(j["rects"][3]["collapsed"].get<bool>());
}

void expectApartAndInside(const std::vector<LabelPlacement>& placed, const std::vector<LabelRequest>& requests,
                          const Box& area, float radius) {
  for (size_t i = 0; i < placed.size(); ++i) {
    EXPECT_TRUE(placed[i].box.inside(area)) << i;
    for (size_t j = 0; j < placed.size(); ++j) {
      if (j != i) {
        EXPECT_FALSE(placed[i].box.overlaps(placed[j].box)) << i << " and " << j;
      }
      Box marker{requests[j].x - radius, requests[j].y - radius, requests[j].x + radius, requests[j].y + radius};
      EXPECT_FALSE(placed[i].box.overlaps(marker)) << "label " << i << " on marker " << j;
    }
  }
}

TEST(LabelPlacement, CoincidentPointsGetSeparateLabels) {
  const Box area{0, 0, 300, 200};
  std::vector<LabelRequest> requests(10, LabelRequest{150, 100, 14, 13});
  auto placed = placeLabels(requests, area, 4);
  ASSERT_EQ(placed.size(), requests.size());
  expectApartAndInside(placed, requests, area, 4);
  EXPECT_FALSE(placed[0].leader);  // the first sits beside its marker
  EXPECT_TRUE(placed[9].leader);   // later ones farther out, with a line back
}

TEST(LabelPlacement, LabelsAtTheEdgesStayInside) {
  const Box area{10, 10, 310, 210};
  std::vector<LabelRequest> requests = {{309, 100, 60, 13}, {11, 11, 60, 13}, {300, 209, 80, 13}, {12, 205, 40, 13},
                                        {305, 105, 60, 13}};
  auto placed = placeLabels(requests, area, 4);
  expectApartAndInside(placed, requests, area, 4);
}

}  // namespace
}  // namespace raylab
