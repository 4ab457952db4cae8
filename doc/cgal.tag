<?xml version='1.0' encoding='UTF-8' standalone='yes' ?>
<!-- The pages of CGAL's documentation that the comments of CGAL RRHT refer to
     with \ref, as CGAL's own tag files name them. Doxyfile's TAGFILES maps
     them to https://doc.cgal.org/latest/, so that they link there. -->
<tagfile>
  <compound kind="group">
    <name>bgl_namedparameters</name>
    <title>Named Parameters</title>
    <filename>BGL/group__bgl__namedparameters.html</filename>
  </compound>
</tagfile>
