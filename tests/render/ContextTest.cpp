// The headless context says what renders it, and EGL's device is chosen by ROLLVIZ_EGL_DEVICE. Built into
// both render test binaries; the device tests run on EGL only (on CI: Mesa's software device, the one it
// lists).
#include "tests/render/ImageCompare.h"
#include "tests/render/Play.h"

#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>
#include <optional>

namespace rv {
namespace {

// sets an environment variable for one test, and puts back what was there
class ScopedEnv {
public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

private:
  const char* name_;
  std::optional<std::string> old_;
};

bool isEgl() {
  return std::string(createHeadlessContext(16, 16)->backend()) == "egl";
}

TEST(Context, SaysWhatRendersIt) {
  const auto ctx = createHeadlessContext(64, 48);
  const RendererInfo& i = ctx->info();
  EXPECT_EQ(i.backend, ctx->backend());
  EXPECT_FALSE(i.context.empty());
  EXPECT_FALSE(i.renderer.empty());
  EXPECT_NE(i.renderer, "?");
  EXPECT_NE(i.vendor, "?");
  int major = 0, minor = 0; // "4.5 (Core Profile) Mesa 22.3.6": at least the 3.2 core the context asks for
  ASSERT_EQ(std::sscanf(i.version.c_str(), "%d.%d", &major, &minor), 2) << i.version;
  EXPECT_GE(major * 10 + minor, 32) << i.version;
  if (isSoftwareRenderer(i.renderer)) {
    EXPECT_TRUE(i.software);
  }
  if (i.backend == "osmesa") {
    EXPECT_TRUE(i.software);
  }
}

TEST(Context, TellsSoftwareRenderersFromGpus) {
  EXPECT_TRUE(isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(isSoftwareRenderer("softpipe"));
  EXPECT_TRUE(isSoftwareRenderer("Mesa X11 / Software Rasterizer"));
  EXPECT_FALSE(isSoftwareRenderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
  EXPECT_FALSE(isSoftwareRenderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
  EXPECT_FALSE(isSoftwareRenderer("AMD Radeon RX 6800 (navi21, LLVM 15.0.6, DRM 3.49, 6.1.0)"));
}

// a device picked by its number in the list renders the same picture as the default choice (on a machine with
// only Mesa, both are llvmpipe: the default takes the surfaceless platform, the variable the software device)
TEST(EglDevice, ADeviceChosenByNumberRendersTheSamePicture) {
  if (!isEgl()) GTEST_SKIP() << "EGL only";
  const auto listed = createHeadlessContext(16, 16)->info().devices;
  if (listed.empty()) GTEST_SKIP() << "this EGL does not enumerate devices";
  const auto p = test::play("chaplygin_ball", 1.0);
  auto render = [&] {
    auto ctx = createHeadlessContext(320, 240);
    p->visual->addTo(ctx->window());
    Image img = capture(ctx->window());
    ctx->window()->RemoveRenderer(p->visual->renderer());
    return std::make_pair(img, ctx->info());
  };
  const auto [usual, usualInfo] = render();
  const std::string last = std::to_string(listed.size() - 1);
  ScopedEnv pick(kEglDeviceVariable, last.c_str());
  const auto [chosen, chosenInfo] = render();
  EXPECT_EQ(chosenInfo.context, "EGL device " + listed.back()) << "the context says which device it is";
  EXPECT_EQ(chosenInfo.devices, listed);
  EXPECT_TRUE(test::isVaried(chosen));
  if (chosenInfo.renderer == usualInfo.renderer) { // the same rasteriser: the same picture
    const auto d = test::compareImages(usual, chosen);
    EXPECT_LT(d.meanAbs, 1.0);
    EXPECT_LT(d.fractionOver, 0.002);
  }
}

TEST(EglDevice, ANumberThatNamesNoDeviceIsBadInputNamingTheVariable) {
  if (!isEgl()) GTEST_SKIP() << "EGL only";
  for (const char* wrong : {"99", "-1", "first", "1x"}) {
    ScopedEnv pick(kEglDeviceVariable, wrong);
    try {
      createHeadlessContext(16, 16);
      ADD_FAILURE() << wrong << " was taken";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(kEglDeviceVariable) + "="), std::string::npos)
          << e.what();
    }
  }
  ScopedEnv empty(kEglDeviceVariable, ""); // set but empty: as if unset
  EXPECT_NO_THROW(createHeadlessContext(16, 16));
}

} // namespace
} // namespace rv
