# Written by unity_groups.py: mdflib's sources in unity batches that share no file-local name.
set_source_files_properties(src/at4block.cpp src/atcomment.cpp src/bigbuffer.cpp src/blockproperty.cpp src/canbusobserver.cpp src/canconfigadapter.cpp src/canmessage.cpp src/cc3block.cpp src/cccomment.cpp src/ccunit.cpp src/cd3block.cpp src/ce3block.cpp src/cg4datawriter.cpp src/cgcomment.cpp src/cgrange.cpp src/channelobserver.cpp
  PROPERTIES UNITY_GROUP mdf0)
set_source_files_properties(src/ca4block.cpp src/cg3block.cpp src/chcomment.cpp src/cncomment.cpp src/cnunit.cpp src/convertersamplequeue.cpp src/copysampleobserver.cpp src/cryptoutil.cpp src/cutf.cpp src/datablock.cpp src/datawriter.cpp src/dbchelper.cpp src/dgcomment.cpp src/dgrange.cpp src/di4block.cpp src/dt3block.cpp
  PROPERTIES UNITY_GROUP mdf1)
set_source_files_properties(src/cc4block.cpp src/cn3block.cpp src/dt4block.cpp src/dv4block.cpp src/dz4block.cpp src/etag.cpp src/ethconfigadapter.cpp src/ethmessage.cpp src/evcomment.cpp src/expatxml.cpp src/fhcomment.cpp src/flexrayconfigadapter.cpp src/flexraymessage.cpp src/hdcomment.cpp src/hoadmindata.cpp src/hocompumethod.cpp
  PROPERTIES UNITY_GROUP mdf2)
set_source_files_properties(src/cg4block.cpp src/hocompuscale.cpp src/hoenumerates.cpp src/hointerval.cpp src/honamedetails.cpp src/hophysicaldimension.cpp src/horevision.cpp src/hoscaleconstraint.cpp src/hounit.cpp src/hounitgroup.cpp src/hounitspecification.cpp src/iattachment.cpp src/iblock.cpp src/ichannel.cpp src/ichannelarray.cpp src/ichannelconversion.cpp
  PROPERTIES UNITY_GROUP mdf3)
set_source_files_properties(src/ch4block.cpp src/ichannelgroup.cpp src/ichannelhierarchy.cpp src/ichannelobserver.cpp src/iconfigadapter.cpp src/idatagroup.cpp src/idblock.cpp src/ievent.cpp src/ifilehistory.cpp src/iheader.cpp src/imetadata.cpp src/isampleobserver.cpp src/isamplereduction.cpp src/isourceinformation.cpp src/ixmlfile.cpp src/ixmlnode.cpp
  PROPERTIES UNITY_GROUP mdf4)
set_source_files_properties(src/cn4block.cpp src/linconfigadapter.cpp src/linmessage.cpp src/littlebuffer.cpp src/md4block.cpp src/mdalternativename.cpp src/mdcomment.cpp src/mdenumerate.cpp src/mdextension.cpp src/mdf3file.cpp src/mdf3timestamp.cpp src/mdf3writer.cpp src/mdf4file.cpp src/mdf4timestamp.cpp src/mdf4writer.cpp src/mdfbuslogger.cpp
  PROPERTIES UNITY_GROUP mdf5)
set_source_files_properties(src/datalistblock.cpp src/hd4block.cpp src/mdfblock.cpp src/mdfenumerates.cpp src/mdffactory.cpp src/mdfhelper.cpp src/mdflogstream.cpp src/mdformula.cpp src/mdftask.cpp src/mdlist.cpp src/mdnumber.cpp src/mdproperty.cpp src/mdstandardattribute.cpp src/mdstring.cpp src/mdsyntax.cpp src/mdvariable.cpp
  PROPERTIES UNITY_GROUP mdf6)
set_source_files_properties(src/dg3block.cpp src/mdfconverter.cpp src/mdffile.cpp src/mostconfigadapter.cpp src/mostmessage.cpp src/platform.cpp src/pr3block.cpp src/rd4block.cpp src/readcache.cpp src/ri4block.cpp src/rv4block.cpp src/samplequeue.cpp src/samplerecordobserver.cpp src/sd4block.cpp src/si4block.cpp src/sicomment.cpp
  PROPERTIES UNITY_GROUP mdf7)
set_source_files_properties(src/dg4block.cpp src/mdfreader.cpp src/sortingconfigadapter.cpp src/sortingtask.cpp src/timestamp.cpp src/tr3block.cpp src/tx3block.cpp src/tx4block.cpp src/vlsddata.cpp src/writer4samplequeue.cpp src/writexml.cpp src/xmlnode.cpp src/zlibutil.cpp
  PROPERTIES UNITY_GROUP mdf8)
set_source_files_properties(src/dl4block.cpp src/mdfwriter.cpp src/validatingtask.cpp
  PROPERTIES UNITY_GROUP mdf9)
set_source_files_properties(src/ev4block.cpp src/sr3block.cpp src/writecache.cpp
  PROPERTIES UNITY_GROUP mdf10)
set_source_files_properties(src/fh4block.cpp
  PROPERTIES UNITY_GROUP mdf11)
set_source_files_properties(src/hd3block.cpp
  PROPERTIES UNITY_GROUP mdf12)
set_source_files_properties(src/hl4block.cpp
  PROPERTIES UNITY_GROUP mdf13)
set_source_files_properties(src/ld4block.cpp
  PROPERTIES UNITY_GROUP mdf14)
set_source_files_properties(src/sr4block.cpp
  PROPERTIES UNITY_GROUP mdf15)
