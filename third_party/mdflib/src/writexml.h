/*
 * Copyright 2022 Ingemar Hedvall
 * SPDX-License-Identifier: MIT
 */

#pragma once
#include "ixmlfile.h"
namespace mdf {
class WriteXml final : public IXmlFile {
 public:
 protected:
};

}  // namespace mdf
