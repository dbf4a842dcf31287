// SPDX-License-Identifier: MIT
#pragma once

#include "core/Base.h"

namespace stroma {

/// SOFA's `<RequiredPlugin name="..."/>` or `pluginName="..."`. Stroma finds the plugin of every
/// component through its plugin index, so this component only records what the scene asked for.
class RequiredPlugin final : public Base {
 public:
  Data<std::vector<std::string>> d_pluginName{
      this, "pluginName", {}, "Names of the plugins the scene declares (SOFA module names too)."};
  Data<bool> d_stopAfterFirstNameFound{this, "stopAfterFirstNameFound", false,
                                       "SOFA option, accepted and without effect."};
  Data<bool> d_requireOne{this, "requireOne", false, "SOFA option, accepted and without effect."};
  Data<bool> d_requireAll{this, "requireAll", true, "SOFA option, accepted and without effect."};

  void init() override;
};

}  // namespace stroma
