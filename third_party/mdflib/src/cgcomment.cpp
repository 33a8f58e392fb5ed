//
// Created by ihedv on 2025-03-07.
//

#include "mdf/cgcomment.h"



namespace mdf {

CgComment::CgComment()
 : MdComment("CG") {

}

}  // namespace mdf