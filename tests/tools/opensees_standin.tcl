# A stand-in for OpenSees's Tcl interpreter (OpenSees is not in Debian): the commands an exported
# script uses, each checking its arguments as OpenSees's parser does (counts, numbers, tags that
# exist), and recording what each analysis is given. It runs a script as it stands:
#   tclsh opensees_standin.tcl SCRIPT.tcl
# and prints, per `analyze`, one line:
#   analysis NODES ELEMENTS {LOADS} {RECORDERS} ALGORITHM
# LOADS: node fx fy fz per load of the patterns defined; RECORDERS: file response per recorder.
# An argument OpenSees would refuse is an error: the script stops and tclsh exits 1.

proc standin_reset {} {
  global nodes materials elements loads recorders algorithm builder
  array unset nodes; array set nodes {}
  array unset materials; array set materials {}
  array unset elements; array set elements {}
  set loads {}
  set recorders {}
  set algorithm ""
  set builder 0
}
standin_reset

proc number {what x} {
  if {![string is double -strict $x]} { error "$what: '$x' is not a number" }
}

proc wipe {} { standin_reset }
proc model {args} {
  global builder
  if {$args ne "BasicBuilder -ndm 3 -ndf 3"} { error "model $args: expected BasicBuilder -ndm 3 -ndf 3" }
  set builder 1
}
proc node {tag x y z} {
  global nodes builder
  if {!$builder} { error "node $tag before model" }
  foreach v [list $x $y $z] { number "node $tag" $v }
  if {[info exists nodes($tag)]} { error "node $tag given twice" }
  set nodes($tag) [list $x $y $z]
}
proc fix {tag args} {
  global nodes
  if {![info exists nodes($tag)]} { error "fix: no node $tag" }
  if {[llength $args] != 3} { error "fix $tag: three flags" }
}
proc mass {tag args} {
  global nodes
  if {![info exists nodes($tag)]} { error "mass: no node $tag" }
  if {[llength $args] != 3} { error "mass $tag: three values" }
  foreach v $args { number "mass $tag" $v }
}
proc uniaxialMaterial {type tag args} {
  global materials
  if {[info exists materials($tag)]} { error "material $tag given twice" }
  switch $type {
    Elastic {
      if {[llength $args] < 1 || [llength $args] > 3} { error "Elastic $tag: E [eta] [Eneg]" }
      foreach v $args { number "Elastic $tag" $v }
    }
    InitStrainMaterial {
      if {[llength $args] != 2} { error "InitStrainMaterial $tag: other strain" }
      if {![info exists materials([lindex $args 0])]} { error "InitStrainMaterial $tag: no material [lindex $args 0]" }
      number "InitStrainMaterial $tag" [lindex $args 1]
    }
    default { error "uniaxialMaterial $type: not used by tbridge" }
  }
  set materials($tag) $type
}
proc element {type tag i j area mat args} {
  global nodes materials elements
  if {$type ne "truss" && $type ne "corotTruss"} { error "element $type: not used by tbridge" }
  foreach n [list $i $j] { if {![info exists nodes($n)]} { error "element $tag: no node $n" } }
  if {![info exists materials($mat)]} { error "element $tag: no material $mat" }
  number "element $tag area" $area
  if {[llength $args] % 2 != 0} { error "element $tag: options in pairs" }
  foreach {key value} $args {
    if {$key ne "-rho" && $key ne "-cMass"} { error "element $tag: option $key" }
    number "element $tag $key" $value
  }
  set elements($tag) $type
}
proc pattern {type tag series body} {
  if {$type ne "Plain" || $series ne "Linear"} { error "pattern $type $tag $series" }
  uplevel #0 $body
}
proc load {tag args} {
  global nodes loads
  if {![info exists nodes($tag)]} { error "load: no node $tag" }
  if {[llength $args] != 3} { error "load $tag: three components" }
  foreach v $args { number "load $tag" $v }
  lappend loads $tag {*}$args
}
proc recorder {type args} {
  global recorders
  if {$type ne "Node"} { error "recorder $type" }
  set file [lindex $args [expr {[lsearch $args -file] + 1}]]
  lappend recorders $file [lindex $args end]
}
foreach command {constraints numberer system test integrator analysis} {
  proc $command {args} {}
}
proc algorithm {name} { global algorithm; set algorithm $name }
proc analyze {steps} {
  global nodes elements loads recorders algorithm
  puts [list analysis [array size nodes] [array size elements] $loads $recorders $algorithm]
  return 0
}

source [lindex $argv 0]
